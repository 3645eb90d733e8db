// Verification: tmdsimpy's 2-DOF elastic dry friction example (2D friction
// with normal load variation, static preload) from its scene file.
// - Stuck levels (s = 1, 10): the contact never slips, so every point of the
//   curve equals the stuck linear system's response (closed form), and the
//   peak is tmdsimpy's 0.70071 s at W = 4.118.
// - Slipping levels (s = 50, 100, 300): the peak is confirmed by time
//   integration of the same system and contact law started on it; the
//   harmonic balance error against it is printed with its run time as H and N grow.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstdio>

#include "cyclone/continuation/NewtonSolve.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/hbm/HarmonicRefinement.hpp"
#include "cyclone/hbm/HillStability.hpp"
#include "cyclone/hbm/PeakMagnitude.hpp"
#include "cyclone/hbm/TimeIntegration.hpp"
#include "cyclone/response/ForcedResponseTrace.hpp"
#include "cyclone/scenes/ForcedResponseScene.hpp"

using namespace cyclone;

namespace {

const char* kScene = CYCLONE_SCENE_DIR "/tmdsimpy_friction2d.yaml";

double maxAbs(const hbm::HarmonicBalanceSystem& sys, const Eigen::VectorXd& X, int dof) {
  const int nc = sys.numCoefficients();
  return hbm::peakMagnitude(sys.aft().harmonics(), Eigen::VectorXd(X.segment(dof * nc, nc)));
}

continuation::Branch trace(const response::ForcedResponseSetup& setup) {
  const auto& sys = *setup.system;
  const auto problem = response::continuationProblem(sys, setup.parameter, 0, setup.excitationScale);
  return continuation::traceBranch(problem, sys.linearizedSolution(setup.continuation.from, setup.excitationScale),
                                   setup.continuation);
}

}  // namespace

TEST(TmdsimpyFriction2D, StuckLevelsEqualTheStuckLinearSystem) {
  for (double s : {1.0, 10.0}) {
    Timer timer;
    auto setup = scenes::loadForcedResponseScene(kScene);
    setup.excitationScale = s;
    setup.continuation.from = 3.6, setup.continuation.to = 4.6;
    setup.continuation.maxStep = 0.02;
    const auto& sys = *setup.system;
    const auto branch = trace(setup);
    ASSERT_TRUE(branch.finished) << branch.stopReason;
    // Stuck: K + diag(kt, kn); the x DOF is decoupled, its static part zero.
    Eigen::Matrix2d Ks = sys.K();
    Ks(0, 0) += 5.0, Ks(1, 1) += 21.0;
    auto stuck = [&](double w) {
      const Eigen::Matrix2cd Z = (Ks - w * w * sys.M()).cast<std::complex<double>>() +
                                 std::complex<double>(0, w) * sys.C().cast<std::complex<double>>();
      return std::abs((Z.inverse() * Eigen::Vector2cd(s, 0.1 * s))(0));
    };
    double worst = 0, peak = 0, peakW = 0;
    for (const auto& pt : branch.points) {
      const double hb = maxAbs(sys, pt.x, 0);
      worst = std::max(worst, std::abs(hb / stuck(pt.parameter) - 1));
      if (hb > peak) peak = hb, peakW = pt.parameter;
    }
    // Closed-form peak of the decoupled x oscillator (m = 1, k = 17, c = cx).
    const double c = sys.C()(0, 0), wPeak = std::sqrt(17 - c * c / 2), xPeak = s / (c * std::sqrt(17 - c * c / 4));
    std::printf("s = %4.0f: %zu points, max relative difference to the stuck linear response %.1e; peak %.5f at "
                "W = %.4f (closed form %.5f at %.4f; tmdsimpy %.5f at 4.118); %.2f s\n",
                s, branch.points.size(), worst, peak, peakW, xPeak, wPeak, 0.70071 * s, timer.seconds());
    EXPECT_LT(worst, 1e-8);
    EXPECT_NEAR(peak / xPeak, 1.0, 2e-4);         // the curve's points sample the peak
    EXPECT_NEAR(peak / (0.70071 * s), 1.0, 2e-4);  // tmdsimpy's published value
    EXPECT_NEAR(peakW, 4.118, 5e-3);
  }
}

TEST(TmdsimpyFriction2D, SlippingPeaksConfirmedByTimeIntegration) {
  for (double s : {50.0, 100.0, 300.0}) {
    Timer timer;
    auto setup = scenes::loadForcedResponseScene(kScene);
    setup.excitationScale = s;
    const auto& sys = *setup.system;
    const auto branch = trace(setup);
    ASSERT_TRUE(branch.finished) << branch.stopReason;
    std::size_t ip = 0;
    for (std::size_t i = 0; i < branch.points.size(); ++i)
      if (maxAbs(sys, branch.points[i].x, 0) > maxAbs(sys, branch.points[ip].x, 0)) ip = i;
    const double w = branch.points[ip].parameter;
    const auto floquet = hbm::hillStability(sys, branch.points[ip].x, w);
    std::printf("s = %3.0f: %zu points in %.2f s, peak max|x| %.5f at W = %.4f (%s)\n", s, branch.points.size(),
                timer.seconds(), maxAbs(sys, branch.points[ip].x, 0), w, floquet.stable ? "stable" : "unstable");
    EXPECT_TRUE(floquet.stable);

    timer.restart();
    hbm::TimeIntegrationOptions ti;
    ti.stepsPerPeriod = 4096;
    ti.excitationScale = s;
    const auto steady = hbm::integrateToSteadyState(sys, w, branch.points[ip].x, ti);
    ASSERT_TRUE(steady.converged);
    const double tiAmp = sys.amplitude(steady.coefficients, 0, 1), tiMax = maxAbs(sys, steady.coefficients, 0);
    std::printf("  time integration (%d steps per period): |x1| %.6f, max|x| %.6f after %d periods, %.2f s\n",
                ti.stepsPerPeriod, tiAmp, tiMax, steady.periods, timer.seconds());

    // Harmonic balance at the same frequency as H and N grow: its error against
    // the time integration falls to the integrator's own level.
    double previous = 0;
    for (auto [H, N] : {std::pair{8, 128}, std::pair{16, 512}, std::pair{32, 2048}}) {
      timer.restart();
      const auto refined = hbm::withHarmonics(sys, hbm::HarmonicSet::upTo(H), N);
      Eigen::VectorXd X = hbm::transferCoefficients(branch.points[ip].x, 2, sys.aft().harmonics(),
                                                    refined->aft().harmonics());
      const auto problem =
          response::continuationProblem(*refined, response::ForcedResponseSetup::Parameter::Omega, 0, s);
      const auto newton = continuation::solveNewton(problem, X, w, 1e-9 * s);
      ASSERT_TRUE(newton.converged) << "H = " << H << ": residual " << newton.residualNorm;
      const double err = std::abs(refined->amplitude(X, 0, 1) / tiAmp - 1);
      std::printf("  H = %2d, N = %4d: |x1| %.6f, relative difference to time integration %.2e (%.3f s)\n", H, N,
                  refined->amplitude(X, 0, 1), err, timer.seconds());
      if (H == 8) {
        EXPECT_LT(err, 2e-2);
      }
      if (H == 32) {
        EXPECT_LT(err, 2e-3);
      }
      if (previous > 1e-4) {
        EXPECT_LT(err, previous);
      }
      previous = err;
    }
  }
}

// Continuation in a contact parameter (mu) at a fixed frequency, at s = 100:
// raising mu sticks the contact (the response tends to the stuck linear
// system's), lowering it to 0 frees it (the response is the linear system
// without the tangential spring); both limits are closed forms.
TEST(TmdsimpyFriction2D, FrictionCoefficientStudyReachesStuckAndFreeLimits) {
  const double w = 3.6, s = 100.0;
  auto response = [&](const hbm::HarmonicBalanceSystem& sys, double kt) {  // |x1| of the linear system
    Eigen::Matrix2d K = sys.K();
    K(0, 0) += kt, K(1, 1) += 21.0;
    const Eigen::Matrix2cd Z = (K - w * w * sys.M()).cast<std::complex<double>>() +
                               std::complex<double>(0, w) * sys.C().cast<std::complex<double>>();
    return std::abs((Z.inverse() * Eigen::Vector2cd(s, 0.1 * s))(0));
  };
  for (auto [to, kt] : {std::pair{20.0, 5.0}, std::pair{0.0, 0.0}}) {
    Timer timer;
    auto setup = scenes::loadForcedResponseScene(kScene);
    setup.excitationScale = s;
    setup.omega = w;
    setup.parameter = response::ForcedResponseSetup::Parameter::ElementParameter;
    setup.parameterElements = {0};
    setup.elementParameter = "mu";
    setup.baseElements = {setup.system->elements()[0].element};
    setup.continuation.from = 0.85, setup.continuation.to = to;
    setup.continuation.maxStep = 0.5;
    const auto problem = response::continuationProblem(setup);
    const auto start = setup.apply(setup.continuation.from);
    const auto branch =
        continuation::traceBranch(problem, setup.system->linearizedSolution(start.first, start.second), setup.continuation);
    ASSERT_TRUE(branch.finished) << branch.stopReason;
    const auto& end = branch.points.back();
    setup.apply(end.parameter);
    const double got = setup.system->amplitude(end.x, 0, 1), want = response(*setup.system, kt);
    std::printf("mu 0.85 -> %.0f at W = %.1f, s = %.0f: %zu points, |x1| %.8f, %s closed form %.8f "
                "(relative %.1e), %.2f s\n",
                to, w, s, branch.points.size(), got, kt > 0 ? "stuck" : "free", want, std::abs(got / want - 1),
                timer.seconds());
    EXPECT_NEAR(got / want, 1.0, 1e-9);
    // At the start the study meets the frequency sweep's point at W = 3.6.
    auto sweep = scenes::loadForcedResponseScene(kScene);
    sweep.excitationScale = s;
    Eigen::VectorXd X = branch.points.front().x;
    const auto omegaProblem =
        response::continuationProblem(*sweep.system, response::ForcedResponseSetup::Parameter::Omega, 0, s);
    Eigen::VectorXd R;
    omegaProblem.residual(X, w, R);
    EXPECT_LT(R.norm(), 1e-8);
  }
}
