// The mesh stage: the built-in sector's parameters or a mesh file, and the mesh's copies
// in Exodus II and Abaqus .inp.
#include <Teuchos_Comm.hpp>

#include <filesystem>
#include <sstream>

#include "cyclone/mesh/AbaqusIO.hpp"
#include "cyclone/mesh/ExodusIO.hpp"
#include "cyclone/mesh/MeshReader.hpp"
#include "cyclone/mesh/ShroudedSectorGenerator.hpp"
#include "cyclone/core/Error.hpp"
#include "cyclone/core/Log.hpp"
#include "cyclone/scenes/SceneSection.hpp"
#include "SceneStages.hpp"

namespace cyclone::scenes {

namespace {

mesh::ShroudedSectorParameters readSectorParameters(SceneSection s) {
  mesh::ShroudedSectorParameters p;
  p.sectors = s.getInt("sectors", p.sectors);
  p.boreRadius = s.getDouble("bore_radius", p.boreRadius);
  p.rimRadius = s.getDouble("rim_radius", p.rimRadius);
  p.discThickness = s.getDouble("disc_thickness", p.discThickness);
  p.bladeHeight = s.getDouble("blade_height", p.bladeHeight);
  p.bladeChord = s.getDouble("blade_chord", p.bladeChord);
  p.bladeThickness = s.getDouble("blade_thickness", p.bladeThickness);
  p.bladeStaggerDeg = s.getDouble("blade_stagger_deg", p.bladeStaggerDeg);
  p.shroudThickness = s.getDouble("shroud_thickness", p.shroudThickness);
  p.shroudWidth = s.getDouble("shroud_width", p.shroudWidth);
  p.meshSize = s.getDouble("mesh_size", p.meshSize);
  p.elementOrder = s.getInt("element_order", p.elementOrder);
  s.rejectUnknownKeys();
  p.validate(s.location());
  return p;
}

}  // namespace

// The mesh stage: built-in generator or a file; the formats of its copies checked.
mesh::Mesh meshStage(SceneSection s, const SceneOverrides& overrides, const std::string& sceneDir,
                     SceneSummary& summary, int& builtInSectors, std::vector<std::string>& copies) {
  builtInSectors = 0;
  const std::string source = s.getString("source", "shrouded_sector");
  copies = s.getStringList("write", {});
  for (const auto& format : copies)
    if (format != "exodus" && format != "inp")
      throw InputError(s.where("write"), "unknown mesh format '" + format + "' (use exodus, inp)");
  SceneSection sector = s.section("shrouded_sector");
  mesh::Mesh mesh;
  if (source == "shrouded_sector") {
    auto p = readSectorParameters(sector);
    if (overrides.meshSize) p.meshSize = *overrides.meshSize;
    mesh = mesh::generateShroudedSector(p);
    builtInSectors = p.sectors;
  } else {
    if (overrides.meshSize)
      throw InputError("--mesh-size", "applies to the built-in sector; this scene reads its mesh from '" + source + "'");
    // The built-in sector's keys do not apply to a mesh read from a file: say so, not
    // "unknown key (known here: )" (issue 20).
    if (s.has("shrouded_sector"))
      throw InputError(s.where("shrouded_sector"), "applies to source: shrouded_sector only; the mesh is read from '" +
                                                       source + "' (remove the block, or the source key)");
    const std::filesystem::path path = std::filesystem::path(source).is_absolute()
                                           ? std::filesystem::path(source)
                                           : std::filesystem::path(sceneDir) / source;
    log::info("reading mesh " + path.string());
    mesh = mesh::readMesh(path.string());
  }
  s.rejectUnknownKeys();
  std::ostringstream line;
  line << "mesh: " << mesh.numNodes() << " nodes, " << mesh.numElements() << " elements (" << mesh.source << ")";
  summary.computed.push_back(line.str());
  return mesh;
}

void writeMeshCopies(const mesh::Mesh& mesh, const std::vector<std::string>& copies, const std::string& outDir,
                     const linalg::Comm& comm, SceneSummary& summary) {
  const bool writer = comm.getRank() == 0;
  for (const auto& format : copies) {
    const std::string path = outDir + (format == "exodus" ? "/mesh.exo" : "/mesh.inp");
    if (writer) {
      if (format == "exodus")
        mesh::writeExodus(path, mesh);
      else
        mesh::writeAbaqusInp(path, mesh);
    }
    summary.written.push_back(path);
  }
}

}  // namespace cyclone::scenes
