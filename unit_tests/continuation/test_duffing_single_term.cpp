// Arclength continuation through the folds of the Duffing oscillator's
// single-term harmonic balance, whose force terms are closed-form:
//   m x'' + c x' + k x + g x^3 = P cos(W t),  x = a cos + b sin,
//   (k - m W^2) a + c W b + 3/4 g (a^2 + b^2) a = P,  (k - m W^2) b - c W a + 3/4 g (a^2 + b^2) b = 0.
// Parameters of the issue: m = 1, c = 0.05, k = 1, g = 0.1, P = 0.18: peak 2.8416 at W = 1.2667.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "SingleTermOscillator.hpp"
#include "cyclone/continuation/ArclengthContinuation.hpp"

using namespace cyclone;

namespace {
const double m = 1, c = 0.05, k = 1, g = 0.1, P = 0.18;

continuation::ContinuationProblem duffing() { return test_support::singleTermOscillator(m, c, k, g, P); }
}  // namespace

TEST(ArclengthContinuation, DuffingSingleTermThroughBothFolds) {
  // Closed-form peak: with s = k - m W^2 + 3/4 g A^2 the amplitude obeys
  // (s^2 + c^2 W^2) A^2 = P^2; dA/dW = 0 gives s = c^2 / (2 m): a fixed point in W.
  const double sPeak = c * c / (2 * m);
  double Wpeak = 1.2, Apeak = 0;
  for (int i = 0; i < 500; ++i) {
    Apeak = P / std::sqrt(sPeak * sPeak + c * c * Wpeak * Wpeak);
    Wpeak = std::sqrt((k + 0.75 * g * Apeak * Apeak - sPeak) / m);
  }
  EXPECT_NEAR(Apeak, 2.8416, 1e-4);
  EXPECT_NEAR(Wpeak, 1.2667, 1e-4);

  continuation::ContinuationOptions o;
  o.from = 0.5;
  o.to = 2.0;
  o.engine = continuation::ContinuationOptions::Engine::Loca;  // LOCA's line searches
  o.initialStep = 0.01;
  o.maxStep = 0.05;
  const double W0 = 0.5, s0 = k - m * W0 * W0;  // a near-linear start: the Newton solve refines it
  Eigen::VectorXd x0(2);
  x0 << P * s0 / (s0 * s0 + c * c * W0 * W0), P * c * W0 / (s0 * s0 + c * c * W0 * W0);
  // The same curve with each of NOX's line searches in LOCA's corrector (a scene's
  // continuation/line_search): on a smooth system they agree.
  using LS = continuation::ContinuationOptions::LineSearch;
  for (const LS search : {LS::FullStep, LS::Backtrack, LS::Polynomial}) {
    SCOPED_TRACE("line search " + std::to_string(int(search)));
    o.lineSearch = search;
    const auto branch = continuation::traceBranch(duffing(), x0, o);
    ASSERT_TRUE(branch.finished) << branch.stopReason;
    ASSERT_GT(branch.points.size(), 50u);
    // Every point solves the system; the amplitude peak matches the closed form; the
    // parameter turns back exactly twice (the two folds of the hardening curve).
    double Amax = 0, Wmax = 0;
    int folds = 0;
    for (std::size_t i = 0; i < branch.points.size(); ++i) {
      const auto& pt = branch.points[i];
      Eigen::VectorXd F;
      duffing().residual(pt.x, pt.parameter, F);
      EXPECT_LT(F.norm(), 1e-9) << "point " << i;
      const double A = pt.x.norm();
      if (A > Amax) Amax = A, Wmax = pt.parameter;
      // (The last point is clamped onto the range end by LOCA, possibly stepping back.)
      if (i >= 2 && i + 1 < branch.points.size()) {
        const double d1 = branch.points[i - 1].parameter - branch.points[i - 2].parameter;
        const double d2 = pt.parameter - branch.points[i - 1].parameter;
        if (std::abs(d1) > 1e-12 && std::abs(d2) > 1e-12 && (d1 > 0) != (d2 > 0)) {
          ++folds;
          std::printf("turning point near W = %.5f, A = %.5f\n", pt.parameter, pt.x.norm());
        }
      }
    }
    std::printf("single-term Duffing: %zu points, peak %.5f at W = %.5f (closed form %.5f at %.5f), %d folds\n",
                branch.points.size(), Amax, Wmax, Apeak, Wpeak, folds);
    EXPECT_EQ(folds, 2);
    EXPECT_NEAR(Amax / Apeak, 1.0, 2e-3);  // the discrete branch samples the peak within a step
    EXPECT_NEAR(branch.points.back().parameter, 2.0, 1e-9);
  }
}

// A branch that folds back and runs out at the bound it started from has not
// traced the rest of the range: p = x (2 - x) from p = 0 rises to its fold at
// p = 1 (x = 1) and returns to p = 0 (x = 2); the range asked for is 0..2.
namespace {

// The two path-shape tests below: p from 0 to 2, first step 0.01, steps up to 0.05.
continuation::ContinuationOptions overZeroToTwo(continuation::ContinuationOptions::Engine engine) {
  continuation::ContinuationOptions o;
  o.engine = engine;
  o.from = 0;
  o.to = 2;
  o.initialStep = 0.01;
  o.maxStep = 0.05;
  return o;
}

}  // namespace

TEST(ArclengthContinuation, BranchReturningToItsStartIsNotTheRangeFinished) {
  continuation::ContinuationProblem fold;
  fold.size = 1;
  fold.residual = [](const Eigen::VectorXd& x, double p, Eigen::VectorXd& F) {
    F.resize(1);
    F(0) = p - x(0) * (2 - x(0));
  };
  fold.jacobian = [](const Eigen::VectorXd& x, double, Eigen::MatrixXd& J) {
    J.resize(1, 1);
    J(0, 0) = -(2 - 2 * x(0));
  };
  using Engine = continuation::ContinuationOptions::Engine;
  for (const Engine engine : {Engine::PredictorCorrector, Engine::Loca}) {
    SCOPED_TRACE(engine == Engine::Loca ? "LOCA" : "predictor-corrector");
    continuation::ContinuationOptions o = overZeroToTwo(engine);
    const auto branch = continuation::traceBranch(fold, Eigen::VectorXd::Zero(1), o);
    EXPECT_FALSE(branch.finished);
    EXPECT_EQ(branch.end, continuation::BranchEnd::ReturnedToStart) << branch.stopReason;
    // The typed details of that end: the range beyond the fold (p = 1) not traced.
    EXPECT_TRUE(branch.returnedToStart) << branch.stopReason;
    EXPECT_NEAR(branch.reached, 1.0, 1e-3) << branch.stopReason;
    double top = 0;
    for (const auto& pt : branch.points) top = std::max(top, pt.parameter);
    EXPECT_NEAR(top, 1.0, 1e-3);  // the fold
    ASSERT_FALSE(branch.points.empty());
    EXPECT_NEAR(branch.points.back().x(0), 2.0, 1e-6);  // back at p = 0 on the other half
  }
}

// A corner of the path that turns by more than 90 degrees while p moves on, as
// a friction contact changing state makes: x = 3 (p - 1) up to p = 1, x = -3 (p
// - 1) after. The hyperplane normal to the incoming direction, (1, 3), meets
// neither piece beyond the corner (their directions' cosine is -0.8), so no
// arclength step with that corrector passes however small. Both engines pass it by
// a step at fixed p past the corner (the predictor-corrector's last resort, LOCA's
// bridgeKink). Every point is checked against the closed form.
// How a trace ended is a type a caller branches on (Branch::end), beside the sentence:
// each way on a problem whose answer is known. x = p over 0..2 ends at the range's end
// (both engines); a range of one point; a budget of 3 points; x^2 + 1 = p, which has no
// solution at p = 0, finds no start.
TEST(ArclengthContinuation, EachWayATraceEndsIsTyped) {
  using continuation::BranchEnd;
  using Engine = continuation::ContinuationOptions::Engine;
  continuation::ContinuationProblem line;
  line.size = 1;
  line.residual = [](const Eigen::VectorXd& x, double p, Eigen::VectorXd& F) {
    F.resize(1);
    F(0) = x(0) - p;
  };
  line.jacobian = [](const Eigen::VectorXd&, double, Eigen::MatrixXd& J) { J = Eigen::MatrixXd::Ones(1, 1); };
  for (const Engine engine : {Engine::PredictorCorrector, Engine::Loca}) {
    SCOPED_TRACE(engine == Engine::Loca ? "LOCA" : "predictor-corrector");
    const auto whole = continuation::traceBranch(line, Eigen::VectorXd::Zero(1), overZeroToTwo(engine));
    EXPECT_TRUE(whole.finished);
    EXPECT_EQ(whole.end, BranchEnd::RangeEnd) << whole.stopReason;
    EXPECT_STREQ(continuation::branchEndName(whole.end), "range_end");
  }
  auto o = overZeroToTwo(Engine::PredictorCorrector);
  o.to = o.from;
  const auto point = continuation::traceBranch(line, Eigen::VectorXd::Zero(1), o);
  EXPECT_EQ(point.end, BranchEnd::SinglePoint) << point.stopReason;
  EXPECT_EQ(point.points.size(), 1u);
  o = overZeroToTwo(Engine::PredictorCorrector);
  o.maxSteps = 3;
  const auto budget = continuation::traceBranch(line, Eigen::VectorXd::Zero(1), o);
  EXPECT_EQ(budget.end, BranchEnd::PointBudget) << budget.stopReason;
  EXPECT_EQ(budget.points.size(), 3u);
  continuation::ContinuationProblem none = line;
  none.residual = [](const Eigen::VectorXd& x, double p, Eigen::VectorXd& F) {
    F.resize(1);
    F(0) = x(0) * x(0) + 1 - p;
  };
  none.jacobian = [](const Eigen::VectorXd& x, double, Eigen::MatrixXd& J) { J = Eigen::MatrixXd::Constant(1, 1, 2 * x(0)); };
  for (const Engine engine : {Engine::PredictorCorrector, Engine::Loca}) {
    SCOPED_TRACE(engine == Engine::Loca ? "LOCA" : "predictor-corrector");
    const auto noStart = continuation::traceBranch(none, Eigen::VectorXd::Constant(1, 0.5), overZeroToTwo(engine));
    EXPECT_FALSE(noStart.finished);
    EXPECT_EQ(noStart.end, BranchEnd::NoStart) << noStart.stopReason;
    EXPECT_TRUE(noStart.points.empty());
  }
}

TEST(ArclengthContinuation, CornerTurningMoreThanARightAngleIsPassed) {
  auto shape = [](double p) { return p < 1 ? 3 * (p - 1) : -3 * (p - 1); };
  continuation::ContinuationProblem corner;
  corner.size = 1;
  corner.residual = [&](const Eigen::VectorXd& x, double p, Eigen::VectorXd& F) {
    F.resize(1);
    F(0) = x(0) - shape(p);
  };
  corner.jacobian = [](const Eigen::VectorXd&, double, Eigen::MatrixXd& J) { J = Eigen::MatrixXd::Ones(1, 1); };
  using Engine = continuation::ContinuationOptions::Engine;
  for (const Engine engine : {Engine::PredictorCorrector, Engine::Loca}) {
    SCOPED_TRACE(engine == Engine::Loca ? "LOCA" : "predictor-corrector");
    continuation::ContinuationOptions o = overZeroToTwo(engine);
    o.stopWhereItTurnsBack = true;
    const auto branch = continuation::traceBranch(corner, Eigen::VectorXd::Constant(1, -3.0), o);
    EXPECT_TRUE(branch.finished) << branch.stopReason;
    ASSERT_FALSE(branch.points.empty());
    EXPECT_NEAR(branch.points.back().parameter, 2.0, 1e-9);
    double previous = -1;
    for (const auto& pt : branch.points) {
      EXPECT_NEAR(pt.x(0), shape(pt.parameter), 1e-8) << "p = " << pt.parameter;
      EXPECT_GT(pt.parameter, previous);  // never back along the path
      previous = pt.parameter;
    }
  }
}
