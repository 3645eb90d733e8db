// Verification: tet10 cantilever beam against beam theory on a refinement
// ladder. Prints error and run time per level and checks the observed order.
//   static: uniform body load q per length, tip deflection (Timoshenko)
//           q L^4 / (8 E I) + q L^2 / (2 kappa G A), kappa = 10(1+nu)/(12+11nu) (Cowper)
//   modes:  first bending (Euler-Bernoulli, 1.87510^2 sqrt(EI / (rho A L^4)))
//           first torsion (pi / 2L) sqrt(G J / (rho Ip)), J = 0.1406 h^4 (square section)
//   free-free: first bending 4.73004^2 sqrt(EI / (rho A L^4)), no supports
// Beam theory differs from 3D elasticity by O((h/L)^2) and the clamp's local
// effects, so the converged FE value is compared with 1-2 % tolerances, while
// the convergence order is measured between FE levels (Richardson). Theory for
// the order: quadratic elements give O(h^4) for compliance and eigenvalues of
// smooth solutions (the free-free beam); the clamped edges are singular
// (2D corner exponent lambda ~ 0.66 for a clamped-free right angle, nu = 0.3),
// which limits the clamped beam's asymptotic rate to 2 lambda ~ 1.3.
#include <Tpetra_Core.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "BoxMesh.hpp"
#include "cyclone/analysis/StaticAnalysis.hpp"
#include "cyclone/core/Log.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/solvers/ModalSolver.hpp"

using namespace cyclone;

namespace {

const double L = 200.0, h = 10.0;
const fe::IsotropicElastic steel{"steel", 2.1e5, 0.3, 7.85e-9};

struct LevelResult {
  int nx;
  long long dofs;
  double tip, bending, torsion, freeBending, seconds;
};

// Mean of the torsional rotation about the beam axis over the tip face, per unit
// mean transverse tip displacement: large for torsion modes, ~0 for bending.
double torsionIndicator(const mesh::Mesh& m, const std::vector<std::array<double, 3>>& u) {
  double rot = 0, trans = 0;
  const auto& tip = m.nodeSet("x1");
  for (auto n : tip) {
    const double y = m.coords[n][1] - h / 2, z = m.coords[n][2] - h / 2;
    const double r2 = y * y + z * z;
    if (r2 > 1e-12) rot += (y * u[n][2] - z * u[n][1]) / std::sqrt(r2);
    trans += std::hypot(u[n][1], u[n][2]);
  }
  return std::abs(rot) / (trans + 1e-300);
}

LevelResult runLevel(int nx) {
  const int ny = std::max(1, nx / 8);
  Timer timer;
  auto beam = test_support::makeBoxMesh(L, h, h, nx, ny, ny, mesh::ElementType::Tet10);
  analysis::StaticProblem problem;
  problem.material = steel;
  problem.fixedNodeSets = {"x0"};
  problem.bodyForce = Eigen::Vector3d(0, -1e-3, 0);
  const auto comm = Tpetra::getDefaultComm();
  const auto result = analysis::solveStatic(beam, problem, comm);
  double tip = 0;
  for (auto n : beam.nodeSet("x1")) tip += result.displacement[n][1];
  tip /= double(beam.nodeSet("x1").size());

  fe::DofMap dofs(beam.numNodes());
  dofs.constrain(beam.nodeSet("x0"));
  dofs.finalize();
  fe::Assembler assembler(beam, dofs, comm);
  auto K = assembler.stiffness(steel);
  auto M = assembler.mass(steel);
  solvers::ModalOptions opt;
  opt.numModes = 8;
  const auto modes = solvers::solveModes(*K, *M, opt);
  double torsion = 0;
  for (int i = 0; i < opt.numModes; ++i) {
    const auto u = assembler.nodalField(*modes.modes, i);
    if (torsionIndicator(beam, u) > 0.5) {
      torsion = modes.frequenciesHz[i];
      break;
    }
  }
  // Free-free: no supports, 6 rigid modes, then the first bending pair.
  fe::DofMap freeDofs(beam.numNodes());
  freeDofs.finalize();
  fe::Assembler freeAssembler(beam, freeDofs, comm);
  auto Kf = freeAssembler.stiffness(steel);
  auto Mf = freeAssembler.mass(steel);
  solvers::ModalOptions freeOpt;
  freeOpt.numModes = 7;
  freeOpt.blockSize = 6;
  freeOpt.shift = -std::pow(2 * M_PI * 1000.0, 2);  // below zero, near the first elastic eigenvalue
  const auto freeModes = solvers::solveModes(*Kf, *Mf, freeOpt);
  return {nx, result.equations, tip, modes.frequenciesHz[0], torsion, freeModes.frequenciesHz[6], timer.seconds()};
}

double observedOrder(double coarse, double mid, double fine) {
  return std::log(std::abs((coarse - mid) / (mid - fine))) / std::log(2.0);
}

}  // namespace

TEST(CantileverBeam, Tet10LadderAgainstBeamTheory) {
  log::setQuiet(true);
  const double E = steel.E, nu = steel.nu, G = E / (2 * (1 + nu)), A = h * h, I = h * h * h * h / 12;
  const double q = -1e-3 * A;
  const double kappa = 10 * (1 + nu) / (12 + 11 * nu);
  const double tipExact = q * std::pow(L, 4) / (8 * E * I) + q * L * L / (2 * kappa * G * A);
  const double bendingExact = std::pow(1.87510407, 2) * std::sqrt(E * I / (steel.rho * A * std::pow(L, 4))) / (2 * M_PI);
  const double J = 0.1406 * std::pow(h, 4), Ip = std::pow(h, 4) / 6;
  const double torsionExact = M_PI / (2 * L) * std::sqrt(G * J / (steel.rho * Ip)) / (2 * M_PI);
  const double freeExact = std::pow(4.73004074, 2) * std::sqrt(E * I / (steel.rho * A * std::pow(L, 4))) / (2 * M_PI);

  std::vector<LevelResult> levels;
  for (int nx : {8, 16, 32}) levels.push_back(runLevel(nx));
  std::printf("\ntet10 cantilever %gx%gx%g: error against beam theory and run time per level\n", L, h, h);
  std::printf("%6s %8s %14s %10s %12s %10s %12s %10s %12s %10s %8s\n", "nx", "dofs", "tip", "err", "f_bend(Hz)",
              "err", "f_tors(Hz)", "err", "f_free(Hz)", "err", "time(s)");
  for (const auto& r : levels)
    std::printf("%6d %8lld %14.6e %10.2e %12.4f %10.2e %12.4f %10.2e %12.4f %10.2e %8.2f\n", r.nx, r.dofs, r.tip,
                r.tip / tipExact - 1, r.bending, r.bending / bendingExact - 1, r.torsion, r.torsion / torsionExact - 1,
                r.freeBending, r.freeBending / freeExact - 1, r.seconds);
  std::printf("reference: tip %.6e, bending %.4f Hz, torsion %.4f Hz, free-free bending %.4f Hz\n", tipExact,
              bendingExact, torsionExact, freeExact);
  const double pTip = observedOrder(levels[0].tip, levels[1].tip, levels[2].tip);
  const double pBend = observedOrder(levels[0].bending, levels[1].bending, levels[2].bending);
  const double pTors = observedOrder(levels[0].torsion, levels[1].torsion, levels[2].torsion);
  const double pFree = observedOrder(levels[0].freeBending, levels[1].freeBending, levels[2].freeBending);
  std::printf("observed order (Richardson, h halved): tip %.2f, bending %.2f, torsion %.2f, free-free %.2f\n", pTip,
              pBend, pTors, pFree);

  const auto& fine = levels.back();
  EXPECT_NEAR(fine.tip / tipExact, 1.0, 0.01);
  EXPECT_NEAR(fine.bending / bendingExact, 1.0, 0.01);
  ASSERT_GT(fine.torsion, 0) << "no torsion mode among the first 8";
  EXPECT_NEAR(fine.torsion / torsionExact, 1.0, 0.02);
  EXPECT_NEAR(fine.freeBending / freeExact, 1.0, 0.01);
  // Smooth problem: O(h^4) for quadratic elements; the coarsest level has one
  // element through the thickness and is pre-asymptotic (3.4 measured), hence 3.
  EXPECT_GT(pFree, 3.0);
  // Clamped: at least the singularity-limited rate 2 lambda ~ 1.3.
  EXPECT_GT(pTip, 1.3);
  EXPECT_GT(pBend, 1.3);
  EXPECT_GT(pTors, 1.3);
  // Refinement must bring the FE answer monotonically down (stiffness-type
  // discretisation: frequencies from above).
  EXPECT_GT(levels[0].bending, levels[1].bending);
  EXPECT_GT(levels[1].bending, levels[2].bending);
}
