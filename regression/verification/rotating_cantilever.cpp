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
#include "cyclone/core/Error.hpp"
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

// The beam along +x from the rotation axis (z), its centre line on the axis: an
// off-axis centre line would add a static in-plane bending load.
mesh::Mesh rotatingBeam(int nx, int ny) {
  auto beam = test_support::makeBoxMesh(L, h, h, nx, ny, ny, mesh::ElementType::Tet10);
  for (auto& x : beam.coords) x[1] -= h / 2, x[2] -= h / 2;
  return beam;
}

struct Level {
  int nx;
  long long dofs;
  double flap[5], lag[5];
  double seconds;
};

Level runLevel(int nx, int ny) {
  Timer timer;
  auto beam = rotatingBeam(nx, ny);
  fe::DofMap dofs(beam.numNodes());
  dofs.constrain(beam.nodeSet("x0"));
  dofs.finalize();
  const auto comm = Tpetra::getDefaultComm();
  const double A = h * h, I = h * h * h * h / 12;
  const double wRef = std::sqrt(steel.E * I / (steel.rho * A * std::pow(L, 4)));
  mesh::RotationAxis axis;  // z through the root: rotation in the xy-plane, flap = z, lag = y
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
      double uy = 0, uz = 0;  // (tip nodes' |u_y| and |u_z| sums)
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

// Past the first axial frequency of the rotating rod the centrifugal softening
// exceeds the axial stiffness: there is no nearby equilibrium, and the solver
// must say so, naming the highest speed it reached, instead of returning garbage.
TEST(RotatingCantilever, UnreachableSpeedIsReportedWithTheLastConvergedSpeed) {
  log::setQuiet(getenv("CYCLONE_VERBOSE") == nullptr);
  auto beam = rotatingBeam(8, 1);
  fe::DofMap dofs(beam.numNodes());
  dofs.constrain(beam.nodeSet("x0"));
  dofs.finalize();
  // First axial frequency of a clamped-free rod: (pi / 2L) sqrt(E / rho) rad/s.
  const double axialRpm = M_PI / (2 * L) * std::sqrt(steel.E / steel.rho) * 60 / (2 * M_PI);
  cyclic::NonlinearPrestressOptions opt;
  opt.minLoadStep = 1e-2;
  // NOX's own lines (its Broyden direction, restarted by a failed Jacobian on purpose,
  // printed "NOX::Direction::Broyden::compute - Unable to compute Jacobian" on every
  // nonlinear prestress) must not reach the user: the solver's report says what failed.
  testing::internal::CaptureStdout();
  testing::internal::CaptureStderr();
  try {
    cyclic::solveNonlinearPrestress(beam, dofs.transform(), steel, 3 * axialRpm, mesh::RotationAxis{}, Tpetra::getDefaultComm(),
                                    opt);
    testing::internal::GetCapturedStdout();
    testing::internal::GetCapturedStderr();
    FAIL() << "a speed three times the axial frequency was reported reached";
  } catch (const SolverError& e) {
    const std::string printed = testing::internal::GetCapturedStdout() + testing::internal::GetCapturedStderr();
    EXPECT_EQ(printed.find("NOX"), std::string::npos) << printed;
    const std::string msg = e.what();
    std::printf("%s\n", msg.c_str());
    EXPECT_NE(msg.find("cannot be reached"), std::string::npos) << msg;
    EXPECT_NE(msg.find("last converged"), std::string::npos) << msg;
  }
  // Well below it the same solver converges, and agrees with the linear prestress to
  // the order of the strains (~1e-3 here).
  const auto nl = cyclic::solveNonlinearPrestress(beam, dofs.transform(), steel, 0.2 * axialRpm, mesh::RotationAxis{},
                                                  Tpetra::getDefaultComm());
  const auto lin = cyclic::solveLinearPrestress(beam, dofs.transform(), steel, 0.2 * axialRpm, mesh::RotationAxis{},
                                                Tpetra::getDefaultComm());
  const auto tip = beam.nodeSet("x1").front();
  std::printf("tip ux at %.0f rpm: nonlinear %.6e, linear %.6e\n", 0.2 * axialRpm, nl.displacement[tip][0],
              lin.displacement[tip][0]);
  EXPECT_GT(nl.displacement[tip][0], 0.0);
  EXPECT_NEAR(nl.displacement[tip][0] / lin.displacement[tip][0], 1.0, 0.1);
}
