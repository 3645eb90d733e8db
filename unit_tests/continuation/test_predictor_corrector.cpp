// The predictor-corrector engine with nothing but the range given: closed-form
// curves traced whole, in few points.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "cyclone/continuation/ArclengthContinuation.hpp"
#include "SingleTermOscillator.hpp"
#include "cyclone/continuation/PeakSearch.hpp"

using namespace cyclone;

namespace {
continuation::ContinuationProblem oscillator(double m, double c, double k, double g, double P) {
  return test_support::singleTermOscillator(m, c, k, g, P);
}
}  // namespace

// A lightly damped linear resonance, Q = 1000 and Q = 125: the whole range in at most
// 300 points with the defaults; with the amplitude as the problem's measure the
// curve's highest point is the peak of the closed form A = P / (2 zeta k sqrt(1 -
// zeta^2)) at W = wn sqrt(1 - 2 zeta^2) to 1e-6 (without it, the best sample is
// within 2 %; the peak search from it agrees to 1e-6).
TEST(PredictorCorrector, LightlyDampedLinearResonanceWholeInFewPoints) {
  for (const double Q : {125.0, 1000.0}) {
    SCOPED_TRACE("Q = " + std::to_string(Q));
    const double m = 1, k = 1, zeta = 1 / (2 * Q), c = 2 * zeta * std::sqrt(k * m), P = 1;
    auto problem = oscillator(m, c, k, 0, P);
    continuation::ContinuationOptions o;  // defaults but the engine and the range
    o.engine = continuation::ContinuationOptions::Engine::PredictorCorrector;
    o.from = 0.5;
    o.to = 1.5;
    const auto samples = continuation::traceBranch(problem, Eigen::VectorXd::Zero(2), o);
    problem.measure = [](const Eigen::VectorXd& x) { return x.norm(); };
    const auto branch = continuation::traceBranch(problem, Eigen::VectorXd::Zero(2), o);
    ASSERT_TRUE(branch.finished) << branch.stopReason;
    EXPECT_LE(branch.points.size(), 300u);
    EXPECT_NEAR(branch.points.back().parameter, 1.5, 1e-12);
    std::size_t top = 0;
    for (std::size_t i = 0; i < branch.points.size(); ++i) {
      Eigen::VectorXd F;
      problem.residual(branch.points[i].x, branch.points[i].parameter, F);
      EXPECT_LT(F.norm(), 1e-9) << "point " << i;
      if (i > 0) {
        EXPECT_GT(branch.points[i].parameter, branch.points[i - 1].parameter);  // no fold: W only rises
      }
      if (branch.points[i].x.norm() > branch.points[top].x.norm()) top = i;
    }
    const double Apeak = P / (2 * zeta * k * std::sqrt(1 - zeta * zeta));
    const double Wpeak = std::sqrt(k / m) * std::sqrt(1 - 2 * zeta * zeta);
    continuation::PeakSearchOptions ps;
    ps.step = 1e-4, ps.maxStep = 1e-3, ps.window = 0.05, ps.parameterTolerance = 1e-7;
    std::size_t sampledTop = 0;
    for (std::size_t i = 0; i < samples.points.size(); ++i)
      if (samples.points[i].x.norm() > samples.points[sampledTop].x.norm()) sampledTop = i;
    const auto& s = samples.points[sampledTop];
    const auto peak = continuation::findLocalPeak(problem, s.x, s.parameter, problem.measure, ps);
    ASSERT_TRUE(peak.found) << peak.reason;
    std::printf("Q = %g: %zu points, %d Newton iterations, %d steps cut; highest point %.10g at W %.8f (closed "
                "form %.10g at %.8f, relative %.1e); without the measure %zu points, best sample %.2e from it, "
                "the peak search from there %.1e\n",
                Q, branch.points.size(), branch.statistics.newtonIterations, branch.statistics.rejectedSteps,
                branch.points[top].x.norm(), branch.points[top].parameter, Apeak, Wpeak,
                branch.points[top].x.norm() / Apeak - 1, samples.points.size(), s.x.norm() / Apeak - 1,
                peak.value / Apeak - 1);
    EXPECT_NEAR(branch.points[top].x.norm() / Apeak, 1.0, 1e-6);
    EXPECT_NEAR(branch.points[top].parameter, Wpeak, 1e-6);
    EXPECT_NEAR(peak.value / Apeak, 1.0, 1e-6);
    EXPECT_NEAR(s.x.norm() / Apeak, 1.0, 0.02);
  }
}

// The hardening Duffing curve (m = 1, c = 0.05, k = 1, g = 0.1, P = 0.18) with the
// defaults: both folds (W turns back twice), the peak of the closed form within the
// sampling, every point a solution.
TEST(PredictorCorrector, DuffingThroughBothFoldsWithDefaults) {
  const double m = 1, c = 0.05, k = 1, g = 0.1, P = 0.18;
  const double sPeak = c * c / (2 * m);
  double Wpeak = 1.2, Apeak = 0;
  for (int i = 0; i < 500; ++i) {  // closed form: s = c^2 / (2 m) at the peak
    Apeak = P / std::sqrt(sPeak * sPeak + c * c * Wpeak * Wpeak);
    Wpeak = std::sqrt((k + 0.75 * g * Apeak * Apeak - sPeak) / m);
  }
  const auto problem = oscillator(m, c, k, g, P);
  continuation::ContinuationOptions o;
  o.engine = continuation::ContinuationOptions::Engine::PredictorCorrector;
  o.from = 0.5;
  o.to = 2.0;
  const auto branch = continuation::traceBranch(problem, Eigen::VectorXd::Zero(2), o);
  ASSERT_TRUE(branch.finished) << branch.stopReason;
  int folds = 0;
  double Amax = 0;
  for (std::size_t i = 0; i < branch.points.size(); ++i) {
    Eigen::VectorXd F;
    problem.residual(branch.points[i].x, branch.points[i].parameter, F);
    EXPECT_LT(F.norm(), 1e-9) << "point " << i;
    Amax = std::max(Amax, branch.points[i].x.norm());
    if (i >= 2) {
      const double d1 = branch.points[i - 1].parameter - branch.points[i - 2].parameter;
      const double d2 = branch.points[i].parameter - branch.points[i - 1].parameter;
      if ((d1 > 0) != (d2 > 0)) ++folds;
    }
  }
  std::printf("Duffing: %zu points, %d Newton iterations, %d steps cut, peak %.5f (closed form %.5f), %d folds\n",
              branch.points.size(), branch.statistics.newtonIterations, branch.statistics.rejectedSteps, Amax, Apeak,
              folds);
  EXPECT_EQ(folds, 2);
  EXPECT_LE(branch.points.size(), 300u);
  EXPECT_NEAR(Amax / Apeak, 1.0, 2e-3);
}
