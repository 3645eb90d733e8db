#include "cyclone/mesh/MeshReader.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "cyclone/core/Error.hpp"
#include "cyclone/mesh/AbaqusIO.hpp"
#include "cyclone/mesh/ExodusIO.hpp"
#include "cyclone/mesh/GmshIO.hpp"

namespace cyclone::mesh {

Mesh readMesh(const std::string& path) {
  namespace fs = std::filesystem;
  if (!fs::exists(path)) throw InputError(path, "mesh file does not exist");
  if (!fs::is_regular_file(path)) throw InputError(path, "not a regular file");
  std::string extension = fs::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  if (extension == ".exo" || extension == ".e" || extension == ".g" || extension == ".ex2") return readExodus(path);
  if (extension == ".inp") return readAbaqusInp(path);
  if (extension == ".msh") return readGmsh(path);
  throw InputError(path, "unknown mesh file extension '" + extension +
                             "' (Cyclone reads .exo/.e/.g/.ex2 Exodus II, .inp CalculiX/Abaqus and .msh gmsh files)");
}

}  // namespace cyclone::mesh
