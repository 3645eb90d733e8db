// The peak continued in a parameter by LOCA on the reduced peak condition
// (continuePeak), on a 1-DOF linear oscillator (m = k = 1) under a unit harmonic
// force, its damping c the parameter: one harmonic, unknowns (x_c, x_s), measure
// x_c^2 + x_s^2, their phase the curve's coordinate. Closed form: the peak at w*^2 = 1 - c^2 / 2 with |x|^2 = 1 / (c^2 (1 -
// c^2 / 4)). Each continued point must lie on it, over two decades of c (continued in
// ln c), and nonsense input is refused with the reason.
#include <gtest/gtest.h>

#include <cmath>

#include "cyclone/continuation/PeakContinuation.hpp"
#include "cyclone/core/Error.hpp"

using namespace cyclone;

namespace {

continuation::PeakTrackingProblem dampedOscillator() {
  continuation::PeakTrackingProblem P;
  P.size = 2;
  P.residual = [](const Eigen::VectorXd& x, double w, double c, Eigen::VectorXd& R) {
    R.resize(2);
    R(0) = (1 - w * w) * x(0) + c * w * x(1) - 1;
    R(1) = -c * w * x(0) + (1 - w * w) * x(1);
  };
  P.jacobian = [](const Eigen::VectorXd&, double w, double c, Eigen::MatrixXd& J) {
    J.resize(2, 2);
    J << 1 - w * w, c * w, -c * w, 1 - w * w;
  };
  continuation::useSquaredAmplitude(P, 0, 1);
  return P;
}

}  // namespace

TEST(PeakContinuation, LinearPeakOverTheDampingOnTheClosedForm) {
  const auto P = dampedOscillator();
  continuation::PeakContinuationOptions o;
  o.from = 0.01, o.to = 1.0;
  // Near the peak at c = 0.01: the response there (x_s = -1 / c at w = 1).
  const auto curve = continuation::continuePeak(P, Eigen::Vector2d(0, -100), 1.0, o);
  ASSERT_TRUE(curve.complete) << curve.stopReason;
  EXPECT_EQ(curve.end, continuation::PeakFollowingEnd::RangeEnd);
  ASSERT_GE(curve.points.size(), 5u);
  EXPECT_NEAR(curve.points.front().parameter, 0.01, 1e-12);
  EXPECT_NEAR(curve.points.back().parameter, 1.0, 1e-9);
  // The peak condition is a difference over the phase theta, (L(theta + h) - L(theta -
  // h)) / 2h with h = 0.15 rad: with |x| = sin(theta) / (c w) and ln w ~ (c / 2)(theta -
  // pi / 2) near the peak, L = ln m = 2 ln sin(theta) - c (theta - pi / 2) + const, whose
  // third derivative there is about 2c; the difference carries h^2 / 6 of it, so its zero
  // is off by (h^2 c / 3) / |L''| = h^2 c / 6 in phase (L'' = -2) and by that times c / 2,
  // h^2 c^2 / 12, in ln w (0.1 h^2 c^2 asserted); m, flat there, by about (h^2 c / 6)^2
  // ((0.2 h^2 c)^2 asserted).
  const double h = o.phaseStep;
  double worstW = 0, worstM = 0;
  for (const auto& pt : curve.points) {
    const double c = pt.parameter, w = std::sqrt(1 - c * c / 2), m = 1 / (c * c * (1 - c * c / 4));
    const double errorW = std::abs(pt.frequency / w - 1), errorM = std::abs(pt.measure / m - 1);
    EXPECT_LT(errorW, 0.1 * h * h * c * c + 1e-9) << "c = " << c;
    EXPECT_LT(errorM, std::pow(0.2 * h * h * c, 2) + 1e-9) << "c = " << c;
    worstW = std::max(worstW, errorW);
    worstM = std::max(worstM, errorM);
  }
  // The smallest peak is the range's end (more damping, lower peak): not inside it.
  EXPECT_EQ(curve.optimum, int(curve.points.size()) - 1);
  EXPECT_FALSE(curve.optimumLocated);
  std::printf("%zu points, %d solves, %.3f s; frequency %.1e, measure %.1e\n", curve.points.size(), curve.solves,
              curve.seconds, worstW, worstM);
}

// A continuation that stops inside the range says so as a type, with its branch's end.
TEST(PeakContinuation, AStopInsideTheRangeIsTyped) {
  const auto P = dampedOscillator();
  continuation::PeakContinuationOptions o;
  o.from = 0.01, o.to = 1.0;
  o.maxSteps = 2;
  const auto curve = continuation::continuePeak(P, Eigen::Vector2d(0, -100), 1.0, o);
  EXPECT_FALSE(curve.complete);
  EXPECT_EQ(curve.end, continuation::PeakFollowingEnd::ContinuationStopped) << curve.stopReason;
  EXPECT_NE(curve.branchEnd, continuation::BranchEnd::RangeEnd);
  EXPECT_NE(curve.branchEnd, continuation::BranchEnd::Running);
  std::printf("%zu points: %s, the branch %s (%s)\n", curve.points.size(),
              continuation::peakFollowingEndName(curve.end), continuation::branchEndName(curve.branchEnd),
              curve.stopReason.c_str());
}

TEST(PeakContinuation, RefusesNonsenseWithTheReason) {
  const auto P = dampedOscillator();
  const Eigen::Vector2d x0(0, -100);
  continuation::PeakContinuationOptions o;
  o.from = 0.1, o.to = 0.1;  // from = to
  EXPECT_THROW(continuation::continuePeak(P, x0, 1.0, o), InputError);
  o.from = -0.1, o.to = 1;  // a logarithmic range through zero
  EXPECT_THROW(continuation::continuePeak(P, x0, 1.0, o), InputError);
  o.from = 0.1;
  EXPECT_THROW(continuation::continuePeak(P, x0, 0.0, o), InputError);            // no frequency
  EXPECT_THROW(continuation::continuePeak(P, Eigen::Vector3d(0, 0, 0), 1.0, o), InputError);  // wrong size
  o.phaseStep = 0.5;
  EXPECT_THROW(continuation::continuePeak(P, x0, 1.0, o), InputError);
  o.phaseStep = 0.1;
  auto noPhase = P;  // no coefficients to take the phase of
  noPhase.phaseCosIndex = noPhase.phaseSinIndex = -1;
  EXPECT_THROW(continuation::continuePeak(noPhase, x0, 1.0, o), InputError);
}

TEST(ContinuationOptions, LocaParameterPerturbationOutsideItsRangeIsRefused) {
  continuation::ContinuationProblem f;
  f.size = 1;
  f.residual = [](const Eigen::VectorXd& x, double p, Eigen::VectorXd& F) { F = x.array() - p; };
  f.jacobian = [](const Eigen::VectorXd&, double, Eigen::MatrixXd& J) { J = Eigen::MatrixXd::Identity(1, 1); };
  continuation::ContinuationOptions o;
  o.engine = continuation::ContinuationOptions::Engine::Loca;
  for (double bad : {0.0, -1e-6, 1.0, std::nan("")}) {
    o.locaParameterPerturbation = bad;
    EXPECT_THROW(continuation::traceBranch(f, Eigen::VectorXd::Zero(1), o), InputError) << bad;
  }
}
