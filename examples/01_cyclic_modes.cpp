// Example 1: the cyclic modes of a bladed-disc sector read from a mesh file.
//   example_cyclic_modes [MESH]   MESH: .inp, .exo or .msh with node sets bore,
//   disc_left/right, shroud_left/right (default: the built-in sector, written as .inp).
#include <cmath>
#include <cstdio>
#include <string>

#include "cyclone/cyclic/CyclicModalAnalysis.hpp"
#include "cyclone/cyclic/CyclicSector.hpp"
#include "cyclone/fe/Environment.hpp"
#include "cyclone/mesh/AbaqusIO.hpp"
#include "cyclone/mesh/MeshReader.hpp"
#include "cyclone/mesh/ShroudedSectorGenerator.hpp"

using namespace cyclone;

int main(int argc, char** argv) {
  Environment env(argc, argv);

  // 1. The mesh file (here written first from the built-in sector, as a mesher would).
  std::string path = argc > 1 ? argv[1] : "";
  if (path.empty()) {
    mesh::ShroudedSectorParameters p;  // 24 sectors
    p.meshSize = 12.0;
    path = "sector.inp";
    mesh::writeAbaqusInp(path, mesh::generateShroudedSector(p));
  }
  const mesh::Mesh mesh = mesh::readMesh(path);

  // 2. The sector: 24 around the z axis; its side faces (disc and shroud) paired under the rotation.
  const int sectors = 24;
  const auto sector = cyclic::makeCyclicSector(mesh, sectors, mesh::RotationAxis{{0, 0, 0}, {0, 0, 1}},
                                               {"disc_left", "shroud_left"}, {"disc_right", "shroud_right"});

  // 3. Three modes per nodal diameter 0..12, titanium, the bore held.
  cyclic::CyclicModalProblem problem;
  problem.fixedNodeSets = {"bore"};
  problem.modesPerNodalDiameter = 3;
  const auto modes = cyclic::solveCyclicModes(mesh, sector, problem, env.comm());

  // 4. The table, and what cyclic symmetry implies: ND 0 and N/2 single modes, the
  //    others pairs of equal frequency; all positive with the bore held.
  bool ok = modes.size() == std::size_t(sectors / 2 + 1);
  for (const auto& nd : modes) {
    const bool single = nd.nodalDiameter == 0 || 2 * nd.nodalDiameter == sectors;
    ok = ok && nd.copies == (single ? 1 : 2) && nd.frequenciesHz.size() == std::size_t(3 * nd.copies);
    std::printf("ND %2d:", nd.nodalDiameter);
    for (std::size_t j = 0; j < nd.frequenciesHz.size(); j += std::size_t(nd.copies)) {
      const double f = nd.frequenciesHz[j];
      ok = ok && f > 0 && (single || std::abs(nd.frequenciesHz[j + 1] / f - 1) < 1e-8);
      std::printf(" %10.2f", f);
    }
    std::printf(" Hz\n");
  }
  std::printf("%s\n", ok ? "cyclic modes: ok" : "cyclic modes: FAILED");
  return ok ? 0 : 1;
}
