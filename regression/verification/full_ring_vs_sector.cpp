// Verification: the full 360-degree model (the sector replicated N times and
// merged) has exactly the frequencies of the cyclic sector over all harmonic
// indices, with multiplicity 1 for k = 0 and N/2 and 2 otherwise. Both of the
// seed's configurations: fixed shroud (disc and shroud faces joined) and
// cantilever (disc faces only).
#include <Tpetra_Core.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "cyclone/core/Log.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/cyclic/CyclicModalAnalysis.hpp"
#include "cyclone/cyclic/FullRing.hpp"
#include "cyclone/fe/Assembler.hpp"
#include "cyclone/mesh/ShroudedSectorGenerator.hpp"
#include "cyclone/solvers/ModalSolver.hpp"

using namespace cyclone;

namespace {

void compareRingAndSector(const std::vector<std::string>& left, const std::vector<std::string>& right,
                          const char* name) {
  mesh::ShroudedSectorParameters p;
  p.sectors = 8;
  p.meshSize = 10.0;
  const auto sectorMesh = mesh::generateShroudedSector(p);
  const auto sector = cyclic::makeCyclicSector(sectorMesh, p.sectors, {}, left, right);
  cyclic::CyclicModalProblem problem;
  problem.fixedNodeSets = {"bore"};
  problem.modesPerNodalDiameter = 4;
  Timer timer;
  const auto modes = cyclic::solveCyclicModes(sectorMesh, sector, problem, Tpetra::getDefaultComm());
  const double sectorSeconds = timer.seconds();

  // Every sector eigenvalue with its multiplicity, below the lowest "last computed" one.
  double ceiling = 1e300;
  std::vector<std::pair<double, int>> expected;  // frequency, k
  for (const auto& hm : modes) {
    ceiling = std::min(ceiling, hm.frequenciesHz.back());
    for (double f : hm.frequenciesHz) expected.push_back({f, hm.nodalDiameter});
  }
  std::sort(expected.begin(), expected.end());
  while (!expected.empty() && expected.back().first > ceiling * (1 - 1e-9)) expected.pop_back();

  timer.restart();
  const auto ring = cyclic::replicateSector(sectorMesh, sector);
  fe::DofMap dofs(ring.mesh.numNodes());
  dofs.constrain(ring.mesh.nodeSet("bore"));
  dofs.finalize();
  fe::Assembler assembler(ring.mesh, dofs, Tpetra::getDefaultComm());
  auto K = assembler.stiffness(problem.material);
  auto M = assembler.mass(problem.material);
  solvers::ModalOptions opt;
  opt.numModes = int(expected.size());
  opt.blockSize = 4;
  const auto full = solvers::solveModes(*K, *M, opt);
  const double ringSeconds = timer.seconds();

  double worst = 0;
  for (std::size_t i = 0; i < expected.size(); ++i)
    worst = std::max(worst, std::abs(full.frequenciesHz[i] / expected[i].first - 1));
  std::printf("%s: %zu ring modes (%ld DOF, %.2f s) vs sector k = 0..%d (%.2f s): max relative difference %.2e\n",
              name, expected.size(), dofs.numFree(), ringSeconds, sector.maxNodalDiameter(), sectorSeconds, worst);
  for (std::size_t i = 0; i < expected.size(); ++i)
    EXPECT_NEAR(full.frequenciesHz[i] / expected[i].first, 1.0, 1e-8)
        << name << " ring mode " << i + 1 << " (sector k = " << expected[i].second << ")";
  // Multiplicities: pairs for 0 < k < N/2 appear twice in the sector list by construction,
  // and the ring reproduces them, so the counts per k must be 1 or 2 per family.
  for (const auto& hm : modes)
    EXPECT_EQ(hm.frequenciesHz.size(), std::size_t(problem.modesPerNodalDiameter * hm.copies));
}

}  // namespace

TEST(FullRingVsSector, FixedShroud) {
  compareRingAndSector({"disc_left", "shroud_left"}, {"disc_right", "shroud_right"}, "fixed shroud");
}

TEST(FullRingVsSector, Cantilever) { compareRingAndSector({"disc_left"}, {"disc_right"}, "cantilever"); }
