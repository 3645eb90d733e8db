// Verification: a rotating tet10 cantilever (hub radius 0, axis normal to its
// length) against the rotating Euler-Bernoulli beam. With
//   eta = Omega sqrt(rho A L^4 / EI),  lambda = omega sqrt(rho A L^4 / EI),
// the first flap (out of the plane of rotation) mode has lambda = 3.5160,
// 3.6816, 4.1373, 6.4495, 11.2023 at eta = 0, 1, 2, 5, 10 (stress stiffening),
// and the first lag (in-plane) mode lambda_lag^2 = lambda_flap^2 - eta^2 (spin
// softening). Linear prestress; Coriolis neglected (it does not couple flap
// and lag of a beam whose flap plane contains the axis).
#include <Tpetra_Core.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "BoxMesh.hpp"
#include "cyclone/core/Log.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/cyclic/Prestress.hpp"
#include "cyclone/solvers/ModalSolver.hpp"

using namespace cyclone;

namespace {

const double L = 100.0, h = 2.0;
const fe::IsotropicElastic steel{"steel", 2.1e5, 0.3, 7.85e-9};
const double etas[5] = {0, 1, 2, 5, 10};
const double flapReference[5] = {3.5160, 3.6816, 4.1373, 6.4495, 11.2023};

struct Level {
  int nx;
  long long dofs;
  double flap[5], lag[5];
  double seconds;
};

Level runLevel(int nx, int ny) {
  Timer timer;
  auto beam = test_support::makeBoxMesh(L, h, h, nx, ny, ny, mesh::ElementType::Tet10);
  fe::DofMap dofs(beam.numNodes());
  dofs.constrain(beam.nodeSet("x0"));
  dofs.finalize();
  const auto comm = Tpetra::getDefaultComm();
  const double A = h * h, I = h * h * h * h / 12;
  const double wRef = std::sqrt(steel.E * I / (steel.rho * A * std::pow(L, 4)));
  fe::Axis axis;  // z through the root: rotation in the xy-plane, flap = z, lag = y
  Level level{nx, dofs.numFree(), {}, {}, 0};
  for (int i = 0; i < 5; ++i) {
    const double omega = etas[i] * wRef;
    const auto state = cyclic::solveLinearPrestress(beam, dofs.transform(), steel, omega * 60 / (2 * M_PI), axis, comm);
    fe::Assembler assembler(beam, dofs, comm);
    auto K = cyclic::tangentStiffness(assembler, steel, &state);
    auto M = assembler.mass(steel);
    solvers::ModalOptions opt;
    opt.numModes = 4;
    const auto modes = solvers::solveModes(*K, *M, opt);
    level.flap[i] = level.lag[i] = 0;
    for (int m = 0; m < opt.numModes; ++m) {
      // Classify by the tip's motion: flap moves in z, lag in y.
      const auto u = assembler.nodalField(*modes.modes, m);
      double uy = 0, uz = 0;
      for (auto n : beam.nodeSet("x1")) uy += std::abs(u[n][1]), uz += std::abs(u[n][2]);
      const double lambda = 2 * M_PI * modes.frequenciesHz[m] / wRef;
      if (uz > 10 * uy && level.flap[i] == 0) level.flap[i] = lambda;
      if (uy > 10 * uz && level.lag[i] == 0) level.lag[i] = lambda;
    }
    // At rest the square beam's flap and lag modes form one double eigenvalue (split
    // slightly: the Kuhn tet split is not symmetric under y <-> z), and the modes may
    // come out as diagonal combinations: take the lower for flap, the upper for lag.
    const double pairGap = std::abs(modes.frequenciesHz[1] / modes.frequenciesHz[0] - 1);
    if (etas[i] == 0 && pairGap < 1e-3) {
      level.flap[i] = 2 * M_PI * modes.frequenciesHz[0] / wRef;
      level.lag[i] = 2 * M_PI * modes.frequenciesHz[1] / wRef;
    }
  }
  level.seconds = timer.seconds();
  return level;
}

}  // namespace

TEST(RotatingCantilever, FlapStiffeningAndLagSoftening) {
  log::setQuiet(true);
  std::vector<Level> levels;
  for (auto [nx, ny] : {std::pair{12, 1}, std::pair{25, 1}, std::pair{50, 2}}) levels.push_back(runLevel(nx, ny));
  std::printf("\nrotating tet10 cantilever %gx%gx%g: flap lambda (relative error) and lag check per level\n", L, h, h);
  for (const auto& lv : levels) {
    std::printf("nx %3d, %6lld dofs, %5.2f s |", lv.nx, lv.dofs, lv.seconds);
    for (int i = 0; i < 5; ++i) std::printf(" eta %2.0f: %.4f (%+.1e)", etas[i], lv.flap[i], lv.flap[i] / flapReference[i] - 1);
    std::printf("\n%38s|", "lag^2 - (flap^2 - eta^2), relative:");
    for (int i = 0; i < 5; ++i)
      std::printf(" %+.1e", (lv.lag[i] * lv.lag[i]) / (lv.flap[i] * lv.flap[i] - etas[i] * etas[i]) - 1);
    std::printf("\n");
  }
  const auto& fine = levels.back();
  for (int i = 0; i < 5; ++i) {
    ASSERT_GT(fine.flap[i], 0) << "no flap mode found at eta " << etas[i];
    ASSERT_GT(fine.lag[i], 0) << "no lag mode found at eta " << etas[i];
    EXPECT_NEAR(fine.flap[i] / flapReference[i], 1.0, 0.01) << "eta " << etas[i];
    EXPECT_NEAR(fine.lag[i] * fine.lag[i] / (fine.flap[i] * fine.flap[i] - etas[i] * etas[i]), 1.0, 0.01)
        << "eta " << etas[i];
  }
}
