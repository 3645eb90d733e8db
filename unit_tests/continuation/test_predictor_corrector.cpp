// The predictor-corrector engine with nothing but the range given: closed-form
// curves traced whole, in few points.
#include <gtest/gtest.h>

#include <algorithm>
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

// The same resonance (Q = 1000) beside a large static offset, as a preloaded contact's
// mean deformation beside the vibration: a third unknown x0 = Fs / k0, constant along
// the curve, 1e3 times the peak amplitude. In one scale group x0 is the yardstick and
// the steps leap over the resonance (printed); with the mean and the oscillation in
// groups of their own (ContinuationProblem::scaleGroups, as the harmonic balance sets
// them), the curve is traced through it and its peak located to 1e-6 of the closed form.
TEST(PredictorCorrector, ResonanceBesideALargeStaticOffsetIsNotSteppedOver) {
  const double m = 1, k = 1, Q = 1000, zeta = 1 / (2 * Q), c = 2 * zeta, P = 1;
  const double Apeak = P / (2 * zeta * k * std::sqrt(1 - zeta * zeta)), Wpeak = std::sqrt(1 - 2 * zeta * zeta);
  const double k0 = 1, Fs = 1e3 * Apeak;
  const auto linear = oscillator(m, c, k, 0, P);
  continuation::ContinuationProblem problem;
  problem.size = 3;
  problem.residual = [&](const Eigen::VectorXd& x, double W, Eigen::VectorXd& F) {
    Eigen::VectorXd f;
    linear.residual(x.tail(2), W, f);
    F.resize(3);
    F << k0 * x(0) - Fs, f;
  };
  problem.jacobian = [&](const Eigen::VectorXd& x, double W, Eigen::MatrixXd& J) {
    Eigen::MatrixXd j;
    linear.jacobian(x.tail(2), W, j);
    J = Eigen::MatrixXd::Zero(3, 3);
    J(0, 0) = k0;
    J.bottomRightCorner(2, 2) = j;
  };
  // max |x(t)| = x0 + amplitude, as a disc's measure holds the mean deformation
  problem.measure = [](const Eigen::VectorXd& x) { return std::abs(x(0)) + x.tail(2).norm(); };
  continuation::ContinuationOptions o;  // defaults but the engine and the range
  o.engine = continuation::ContinuationOptions::Engine::PredictorCorrector;
  o.from = 0.5, o.to = 1.5;
  auto highest = [&](const continuation::Branch& b) {  // the largest amplitude on the curve
    double top = 0;
    for (const auto& pt : b.points) top = std::max(top, pt.x.tail(2).norm());
    return top;
  };
  auto inBand = [&](const continuation::Branch& b) {  // points within the half-power band
    int count = 0;
    for (const auto& pt : b.points) count += std::abs(pt.parameter - 1) <= zeta;
    return count;
  };
  const auto oneGroup = continuation::traceBranch(problem, Eigen::VectorXd::Zero(3), o);
  problem.scaleGroups = {0, 1, 1};
  const auto grouped = continuation::traceBranch(problem, Eigen::VectorXd::Zero(3), o);
  ASSERT_TRUE(grouped.finished) << grouped.stopReason;
  std::printf("one scale group: %zu points (%d in the half-power band), highest amplitude %.10g of the peak; mean "
              "and oscillation apart: %zu points (%d in the band), highest %.10g (closed form %.10g)\n",
              oneGroup.points.size(), inBand(oneGroup), highest(oneGroup) / Apeak, grouped.points.size(),
              inBand(grouped), highest(grouped), Apeak);
  EXPECT_LE(grouped.points.size(), 300u);
  EXPECT_GE(inBand(grouped), 8);  // the resonance drawn, not a spike between far points
  EXPECT_NEAR(highest(grouped) / Apeak, 1.0, 1e-6);
  std::size_t top = 0;
  for (std::size_t i = 0; i < grouped.points.size(); ++i)
    if (grouped.points[i].x.tail(2).norm() > grouped.points[top].x.tail(2).norm()) top = i;
  EXPECT_NEAR(grouped.points[top].parameter, Wpeak, 1e-6);
  EXPECT_NEAR(grouped.points[top].x(0), Fs / k0, 1e-9 * Fs);
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
