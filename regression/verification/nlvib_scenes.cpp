// Verification: NLvib's example 02 (two DOFs, cubic springs) from its scene file:
// the curve is traced by harmonic balance + continuation, and its peak is
// confirmed by time integration of the same system started on the peak's
// periodic solution: if that solution were not a stable periodic motion of the
// system, the integration would drift away from it.
#include <Tpetra_Core.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "cyclone/core/Timer.hpp"
#include "cyclone/hbm/HillStability.hpp"
#include "cyclone/hbm/TimeIntegration.hpp"
#include "cyclone/scenes/ForcedResponseScene.hpp"

using namespace cyclone;

TEST(NlvibScenes, Example02PeakConfirmedByTimeIntegration) {
  Timer timer;
  auto setup = scenes::loadForcedResponseScene(CYCLONE_SCENE_DIR "/nlvib_02.yaml");
  auto& sys = *setup.system;
  const auto problem = scenes::continuationProblem(sys, scenes::ForcedResponseSetup::Parameter::Omega);
  const auto branch = continuation::traceBranch(problem, sys.linearSolution(setup.continuation.from), setup.continuation);
  ASSERT_TRUE(branch.finished) << branch.stopReason;
  std::size_t peak = 0;
  for (std::size_t i = 0; i < branch.points.size(); ++i)
    if (sys.amplitude(branch.points[i].x, 0, 1) > sys.amplitude(branch.points[peak].x, 0, 1)) peak = i;
  const auto& pt = branch.points[peak];
  const double hbPeak = sys.amplitude(pt.x, 0, 1);
  const auto floquet = hbm::hillStability(sys, pt.x, pt.parameter);
  const double tTrace = timer.seconds();
  timer.restart();
  hbm::TimeIntegrationOptions options;
  options.stepsPerPeriod = 2048;
  const auto ti = hbm::integrateToSteadyState(sys, pt.parameter, pt.x, options);
  const double tiPeak = sys.amplitude(ti.coefficients, 0, 1);
  std::printf("NLvib 02: %zu points, peak |x1| of DOF 1 = %.6f at W = %.5f (%s, max Re %.2e; %.2f s); "
              "time integration from it: %.6f after %d periods (%.2f s), relative difference %.1e\n",
              branch.points.size(), hbPeak, pt.parameter, floquet.stable ? "stable" : "unstable",
              floquet.maxRealPart, tTrace, tiPeak, ti.periods, timer.seconds(), std::abs(tiPeak / hbPeak - 1));
  EXPECT_TRUE(floquet.stable);
  ASSERT_TRUE(ti.converged);
  EXPECT_NEAR(tiPeak / hbPeak, 1.0, 1e-4);
}
