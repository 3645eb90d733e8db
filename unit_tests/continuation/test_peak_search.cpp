// The peak search at fixed parameters (PeakSearch.hpp) on the single-term
// harmonic balance of a damped oscillator, whose peaks are closed-form:
//   (k - m W^2 + 3/4 g A^2) a + c W b = P,  (k - m W^2 + 3/4 g A^2) b - c W a = 0,  A^2 = a^2 + b^2.
// With s = k - m W^2 + 3/4 g A^2 the amplitude obeys (s^2 + c^2 W^2) A^2 = P^2.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <utility>

#include "cyclone/continuation/PeakSearch.hpp"

using namespace cyclone;

namespace {
const double m = 1, c = 0.05, k = 1, P = 0.18;

continuation::ContinuationProblem oscillator(double g) {
  continuation::ContinuationProblem p;
  p.size = 2;
  p.residual = [g](const Eigen::VectorXd& x, double W, Eigen::VectorXd& F) {
    const double a = x(0), b = x(1), s = k - m * W * W + 0.75 * g * (a * a + b * b);
    F.resize(2);
    F << s * a + c * W * b - P, s * b - c * W * a;
  };
  p.jacobian = [g](const Eigen::VectorXd& x, double W, Eigen::MatrixXd& J) {
    const double a = x(0), b = x(1), s = k - m * W * W + 0.75 * g * (a * a + b * b);
    J.resize(2, 2);
    J << s + 1.5 * g * a * a, c * W + 1.5 * g * a * b, -c * W + 1.5 * g * a * b, s + 1.5 * g * b * b;
  };
  return p;
}

// The linear solution at W (a start guess).
Eigen::VectorXd linearGuess(double W) {
  const double s = k - m * W * W, d = s * s + c * c * W * W;
  return Eigen::Vector2d(P * s / d, P * c * W / d);
}

double amplitude(const Eigen::VectorXd& x) { return x.norm(); }
}  // namespace

// Linear (g = 0): the peak of A(W) = P / sqrt((k - m W^2)^2 + c^2 W^2) is at
// W^2 = k/m - c^2 / (2 m^2).
TEST(PeakSearch, LinearOscillatorPeakMatchesClosedForm) {
  const double Wpeak = std::sqrt(k / m - c * c / (2 * m * m));
  const double Apeak = P / std::sqrt(std::pow(k - m * Wpeak * Wpeak, 2) + c * c * Wpeak * Wpeak);
  continuation::PeakSearchOptions o;
  o.step = 1e-3, o.maxStep = 1e-2, o.window = 0.3, o.parameterTolerance = 1e-7;
  for (const double W0 : {0.9, 1.1, Wpeak}) {
    const auto r = continuation::findLocalPeak(oscillator(0), linearGuess(W0), W0, amplitude, o);
    std::printf("linear oscillator from W = %.4f: peak %.9f at W = %.9f (closed form %.9f at %.9f), %d solves\n", W0,
                r.value, r.parameter, Apeak, Wpeak, r.solves);
    ASSERT_TRUE(r.found) << r.reason;
    // The path: every accepted point solves the system, the best among them.
    ASSERT_FALSE(r.path.empty());
    bool bestOnPath = false;
    for (const auto& [W, x] : r.path) {
      Eigen::VectorXd F;
      oscillator(0).residual(x, W, F);
      EXPECT_LT(F.norm(), 1e-9);
      bestOnPath = bestOnPath || (W == r.parameter && x == r.x);
    }
    EXPECT_TRUE(bestOnPath);
    EXPECT_NEAR(r.parameter, Wpeak, 1e-6);
    EXPECT_NEAR(r.value / Apeak, 1.0, 1e-9);  // flat at the top: the value is far better than the parameter
  }
}

// The hardening Duffing's upper-branch peak in closed form: s = c^2 / (2 m) (dA/dW = 0),
// W and A by fixed point. Returns {W, A}.
static std::pair<double, double> upperBranchPeak(double g) {
  const double sPeak = c * c / (2 * m);
  double Wpeak = 1.2, Apeak = 0;
  for (int i = 0; i < 500; ++i) {
    Apeak = P / std::sqrt(sPeak * sPeak + c * c * Wpeak * Wpeak);
    Wpeak = std::sqrt((k + 0.75 * g * Apeak * Apeak - sPeak) / m);
  }
  return {Wpeak, Apeak};
}

// Hardening Duffing (g = 0.1): walking up the upper branch from W = 1 finds the peak
// s = c^2 / (2 m) (dA/dW = 0), which lies before the fold where the branch ends.
TEST(PeakSearch, DuffingUpperBranchPeakMatchesClosedForm) {
  const double g = 0.1;
  const auto [Wpeak, Apeak] = upperBranchPeak(g);
  continuation::PeakSearchOptions o;
  o.step = 5e-3, o.maxStep = 2e-2, o.window = 0.6, o.parameterTolerance = 1e-7;
  const auto r = continuation::findLocalPeak(oscillator(g), linearGuess(1.0), 1.0, amplitude, o);
  std::printf("Duffing upper branch: peak %.9f at W = %.9f (closed form %.9f at %.9f), %d solves\n", r.value,
              r.parameter, Apeak, Wpeak, r.solves);
  ASSERT_TRUE(r.found) << r.reason;
  EXPECT_NEAR(r.parameter, Wpeak, 1e-5);
  EXPECT_NEAR(r.value / Apeak, 1.0, 1e-8);
}

// Walking down the Duffing's lower branch from W = 1.5, the amplitude rises until
// the branch folds (the jump-up point, the least W of the branch right of the
// backbone, s < 0). The search must stop there and say so, not jump to the upper
// branch and report its peak.
TEST(PeakSearch, StopsAtAFoldWithoutJumpingToAnotherBranch) {
  const double g = 0.1;
  // The fold: the least W over A of W^2 = k + 3/4 g A^2 + sqrt(P^2 / A^2 - c^2 W^2) (fixed point in W).
  double Wfold = 1e9, Afold = 0;
  for (double A = 0.05; A < 2.8; A += 1e-4) {
    double W = 1.0;
    bool ok = true;
    for (int i = 0; i < 200 && ok; ++i) {
      const double q = P * P / (A * A) - c * c * W * W;
      if (q < 0) ok = false;
      else W = std::sqrt((k + 0.75 * g * A * A + std::sqrt(q)) / m);
    }
    if (ok && W < Wfold) Wfold = W, Afold = A;
  }
  continuation::PeakSearchOptions o;
  o.step = 5e-3, o.maxStep = 2e-2, o.minStep = 1e-7, o.window = 0.6;
  const auto r = continuation::findLocalPeak(oscillator(g), linearGuess(1.5), 1.5, amplitude, o);
  std::printf("Duffing lower branch: stopped at W = %.6f, A = %.6f (fold at %.6f, %.6f): %s\n", r.parameter, r.value,
              Wfold, Afold, r.reason.c_str());
  EXPECT_FALSE(r.found);
  EXPECT_NE(r.reason.find("fold"), std::string::npos) << r.reason;
  EXPECT_NEAR(r.parameter, Wfold, 2e-3);
  EXPECT_LT(r.value, 1.01 * Afold);  // still on the lower branch (the upper one is above 2 here)
}

// The same walk carried past the fold (findPeakPastFold): the arclength trace from the
// walk's start rounds the jump-up fold, climbs the unstable middle branch to the jump-down
// fold and comes back along the upper branch over its top, the closed-form peak of the
// upper branch (s = c^2 / (2 m)).
TEST(PeakSearch, PastAFoldTheUpperBranchPeakIsFound) {
  const double g = 0.1;
  const auto [Wpeak, Apeak] = upperBranchPeak(g);
  continuation::PeakSearchOptions o;
  o.step = 5e-3, o.maxStep = 2e-2, o.minStep = 1e-7, o.window = 0.6;
  const auto walk = continuation::findLocalPeak(oscillator(g), linearGuess(1.5), 1.5, amplitude, o);
  ASSERT_FALSE(walk.found);
  const auto r = continuation::findPeakPastFold(oscillator(g), walk, amplitude, o, 400);
  std::printf("Duffing past the lower branch's fold at W = %.6f: peak %.9f at W = %.9f (closed form %.9f at %.9f), "
              "%d solves\n",
              walk.parameter, r.value, r.parameter, Apeak, Wpeak, r.solves);
  ASSERT_TRUE(r.found) << r.reason;
  EXPECT_NEAR(r.parameter, Wpeak, 1e-4);
  EXPECT_NEAR(r.value / Apeak, 1.0, 1e-7);
  // A trace that cannot reach the top (a window that ends before it) says so, not found.
  o.window = 0.5 * (1.5 - walk.parameter);
  const auto walkShort = continuation::findLocalPeak(oscillator(g), linearGuess(1.5), 1.5, amplitude, o);
  const auto none = continuation::findPeakPastFold(oscillator(g), walkShort, amplitude, o, 400);
  EXPECT_FALSE(none.found) << none.value << " at " << none.parameter;
}

// Beyond a fold Newton may converge to a solution of another branch: here
// F = (x^2 - p)(x + 1) has the branch x = sqrt(p), which ends at p = 0, and the
// branch x = -1 everywhere. Walking down from p = 1 with the measure -x rising, the
// search must not take x = -1 below p = 0 for its next point (and then call the
// fold a bracketed peak): it stops at the fold and says so.
TEST(PeakSearch, ASolutionOnAnotherBranchIsNotTakenForTheNextPoint) {
  continuation::ContinuationProblem p;
  p.size = 1;
  p.residual = [](const Eigen::VectorXd& x, double q, Eigen::VectorXd& F) {
    F.resize(1);
    F(0) = (x(0) * x(0) - q) * (x(0) + 1);
  };
  p.jacobian = [](const Eigen::VectorXd& x, double q, Eigen::MatrixXd& J) {
    J.resize(1, 1);
    J(0, 0) = 2 * x(0) * (x(0) + 1) + (x(0) * x(0) - q);
  };
  continuation::PeakSearchOptions o;
  o.step = 0.05, o.maxStep = 0.2, o.minStep = 1e-9, o.window = 2;
  const auto r = continuation::findLocalPeak(p, Eigen::VectorXd::Ones(1), 1.0,
                                             [](const Eigen::VectorXd& x) { return -x(0); }, o);
  std::printf("branch x = sqrt(p) walked down: stopped at p = %.3g, x = %.3g: %s\n", r.parameter, -r.value,
              r.reason.c_str());
  EXPECT_FALSE(r.found);
  EXPECT_NE(r.reason.find("fold"), std::string::npos) << r.reason;
  EXPECT_GE(r.parameter, 0.0);
  EXPECT_LT(r.parameter, 1e-3);
  EXPECT_LT(-r.value, 0.05);  // on the branch x = sqrt(p), near its end
}

// A measure that is negative everywhere, highest at the start: the start is the
// best point (not a left-over initial value), and with its neighbours lower the
// search brackets it there: g = -1 - (p - 0.3)^2 along x = p.
TEST(PeakSearch, NegativeMeasurePeakAtTheStart) {
  continuation::ContinuationProblem p;
  p.size = 1;
  p.residual = [](const Eigen::VectorXd& x, double q, Eigen::VectorXd& F) {
    F.resize(1);
    F(0) = x(0) - q;
  };
  p.jacobian = [](const Eigen::VectorXd&, double, Eigen::MatrixXd& J) { J = Eigen::MatrixXd::Ones(1, 1); };
  continuation::PeakSearchOptions o;
  o.step = 0.01, o.maxStep = 0.05, o.window = 1, o.parameterTolerance = 1e-8;
  const auto r = continuation::findLocalPeak(
      p, Eigen::VectorXd::Constant(1, 0.3), 0.3, [](const Eigen::VectorXd& x) { return -1 - std::pow(x(0) - 0.3, 2); },
      o);
  ASSERT_TRUE(r.found) << r.reason;
  EXPECT_NEAR(r.parameter, 0.3, 1e-8);
  EXPECT_NEAR(r.value, -1.0, 1e-15);
  ASSERT_EQ(r.x.size(), 1);
  EXPECT_NEAR(r.x(0), 0.3, 1e-8);
}
