// Verification: the cyclic sector's modes per nodal diameter by LOBPCG + MueLu
// (no factorization) agree with shift-invert Krylov-Schur on the CHOLMOD
// factorization (the reference) for k = 0, an interior k (two copies: every
// frequency a pair of equal eigenvalues) and k = N/2; fixed shroud, bore fixed.
//
// Tolerance 1e-8 relative on frequencies: both solvers stop at relative residuals
// of 1e-10, and an eigenvalue's error is of the order of the residual squared over
// the gap to its neighbours, so converged runs agree to about 1e-11 (observed:
// 2e-11 or better). 1e-8 leaves room for rounding and is far below what a real
// disagreement gives: a missed member of a pair, a skipped or spurious mode shifts
// the sorted lists against each other by a whole spectral gap (at least 4 %
// between the distinct frequencies here), and a stalled vector fails the solver's
// own backward-error check (1e-6) or leaves an error near its residual, >> 1e-8.
#include <Tpetra_Core.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "cyclone/core/Log.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/cyclic/CyclicModalAnalysis.hpp"
#include "cyclone/mesh/ShroudedSectorGenerator.hpp"

using namespace cyclone;

TEST(CyclicLobpcg, AgreesWithShiftInvertPerNodalDiameter) {
  log::setQuiet(true);
  mesh::ShroudedSectorParameters p;
  p.sectors = 12;  // k = 0 and 6 here once met an indefinite MueLu V-cycle (see IterativeSolver.cpp)
  p.meshSize = 12.0;
  const auto sectorMesh = mesh::generateShroudedSector(p);
  const auto sector = cyclic::makeCyclicSector(sectorMesh, p.sectors, {}, {"disc_left", "shroud_left"},
                                               {"disc_right", "shroud_right"});
  cyclic::CyclicModalProblem problem;
  problem.fixedNodeSets = {"bore"};
  problem.modesPerNodalDiameter = 4;
  const std::vector<int> harmonics = {0, 3, p.sectors / 2};
  std::printf("\ncyclic sector (%d sectors, %lld nodes): LOBPCG + MueLu against shift-invert\n", p.sectors,
              (long long)sectorMesh.numNodes());
  for (int k : harmonics) {
    problem.nodalDiameters = {k};
    problem.method = solvers::EigenMethod::ShiftInvert;
    Timer timer;
    const auto reference = cyclic::solveCyclicModes(sectorMesh, sector, problem, Tpetra::getDefaultComm()).front();
    const double referenceSeconds = timer.seconds();
    problem.method = solvers::EigenMethod::Lobpcg;
    timer.restart();
    const auto lobpcg = cyclic::solveCyclicModes(sectorMesh, sector, problem, Tpetra::getDefaultComm()).front();
    const double lobpcgSeconds = timer.seconds();
    ASSERT_EQ(lobpcg.frequenciesHz.size(), reference.frequenciesHz.size()) << "k = " << k;
    ASSERT_EQ(reference.frequenciesHz.size(), std::size_t(problem.modesPerNodalDiameter * reference.copies));
    double worst = 0;
    for (std::size_t i = 0; i < reference.frequenciesHz.size(); ++i)
      worst = std::max(worst, std::abs(lobpcg.frequenciesHz[i] / reference.frequenciesHz[i] - 1));
    std::printf("  k = %d: %lld equations, %zu modes %.1f .. %.1f Hz, max relative difference %.2e; "
                "shift-invert %.2f s, LOBPCG %.2f s\n",
                k, reference.equations, reference.frequenciesHz.size(), reference.frequenciesHz.front(),
                reference.frequenciesHz.back(), worst, referenceSeconds, lobpcgSeconds);
    for (std::size_t i = 0; i < reference.frequenciesHz.size(); ++i)
      EXPECT_NEAR(lobpcg.frequenciesHz[i] / reference.frequenciesHz[i], 1.0, 1e-8) << "k = " << k << ", mode " << i + 1;
  }
}
