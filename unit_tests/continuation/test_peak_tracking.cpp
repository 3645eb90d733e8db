// Peak tracking (PeakTracking.hpp) against the closed form of the single-term
// Duffing oscillator: x = a cos(wt) + b sin(wt), A^2 = a^2 + b^2,
//   (k - m w^2 + 3/4 k3 A^2) a + c w b = P,   (k - m w^2 + 3/4 k3 A^2) b - c w a = 0.
// Its amplitude is largest in w where dF/dw = 0 for F = [(k - m w^2 + 3/4 k3 A^2)^2 +
// (c w)^2] A^2 - P^2, i.e. D = k - m w^2 + 3/4 k3 A^2 = c^2 / (2 m); then
// A^2 (D^2 + c^2 w^2) = P^2 with m w^2 = k + 3/4 k3 A^2 - D, one equation in A. The
// peak is followed in the force P (through a range where it moves by a factor 4 in
// amplitude) and in the cubic stiffness k3 (hardening and softening), each point
// against that closed form.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "cyclone/continuation/PeakTracking.hpp"

using namespace cyclone;

namespace {

constexpr double m = 1.0, c = 0.05, k = 1.0;

struct ClosedFormPeak {
  double A, w;
};

// The peak for force P and cubic stiffness k3: bisection on A (the left side grows with A).
ClosedFormPeak closedForm(double P, double k3) {
  const double D = c * c / (2 * m);
  auto f = [&](double A) {
    const double w2 = (k + 0.75 * k3 * A * A - D) / m;
    return A * A * (D * D + c * c * w2) - P * P;
  };
  double lo = 0, hi = 1;
  while (f(hi) < 0) hi *= 2;
  for (int i = 0; i < 200; ++i) (f(0.5 * (lo + hi)) < 0 ? lo : hi) = 0.5 * (lo + hi);
  const double A = 0.5 * (lo + hi);
  return {A, std::sqrt((k + 0.75 * k3 * A * A - D) / m)};
}

// The system with the parameter either the force (k3 fixed) or k3 (the force fixed).
continuation::PeakTrackingProblem duffing(bool forceIsParameter, double fixed) {
  continuation::PeakTrackingProblem P;
  P.size = 2;
  P.residual = [=](const Eigen::VectorXd& x, double w, double p, Eigen::VectorXd& R) {
    const double force = forceIsParameter ? p : fixed, k3 = forceIsParameter ? fixed : p;
    const double D = k - m * w * w + 0.75 * k3 * x.squaredNorm();
    R.resize(2);
    R << D * x(0) + c * w * x(1) - force, D * x(1) - c * w * x(0);
  };
  P.jacobian = [=](const Eigen::VectorXd& x, double w, double p, Eigen::MatrixXd& J) {
    const double k3 = forceIsParameter ? fixed : p;
    const double D = k - m * w * w + 0.75 * k3 * x.squaredNorm();
    J.resize(2, 2);
    J << D + 1.5 * k3 * x(0) * x(0), c * w + 1.5 * k3 * x(0) * x(1), -c * w + 1.5 * k3 * x(1) * x(0),
        D + 1.5 * k3 * x(1) * x(1);
  };
  continuation::useSquaredAmplitude(P, 0, 1);
  return P;
}

// The start: the closed form's point (a, b) at the peak.
Eigen::VectorXd peakPoint(double P, const ClosedFormPeak& f) {
  const double D = c * c / (2 * m), a = P * D / (D * D + c * c * f.w * f.w);
  return Eigen::Vector2d(a, c * f.w * a / D);
}

double worstError(const continuation::PeakCurve& curve, bool forceIsParameter, double fixed) {
  double worst = 0;
  for (const auto& pt : curve.points) {
    const double P = forceIsParameter ? pt.parameter : fixed, k3 = forceIsParameter ? fixed : pt.parameter;
    const auto f = closedForm(P, k3);
    worst = std::max({worst, std::abs(std::sqrt(pt.measure) / f.A - 1), std::abs(pt.frequency / f.w - 1)});
  }
  return worst;
}

}  // namespace

TEST(PeakTracking, DuffingPeakFollowedInTheForceMatchesTheClosedForm) {
  const double k3 = 0.1, P0 = 0.01;
  const auto f0 = closedForm(P0, k3);
  continuation::ContinuationOptions o;
  o.from = P0, o.to = 0.06, o.tolerance = 1e-12;
  const auto curve = continuation::trackPeak(duffing(true, k3), peakPoint(P0, f0), f0.w, o);
  ASSERT_TRUE(curve.finished) << curve.stopReason;
  const double err = worstError(curve, true, k3);
  const auto& last = curve.points.back();
  std::printf("force %.3g -> %.3g: %zu points, peak amplitude %.4f -> %.4f at %.4f -> %.4f rad/s; worst relative "
              "error against the closed form %.2e\n",
              P0, o.to, curve.points.size(), f0.A, std::sqrt(last.measure), f0.w, last.frequency, err);
  EXPECT_NEAR(last.parameter, o.to, 1e-12);
  EXPECT_GT(std::sqrt(last.measure), 4 * f0.A);  // the peak moved far
  EXPECT_LT(err, 1e-8);
}

TEST(PeakTracking, DuffingPeakFollowedInTheCubicStiffnessThroughZero) {
  const double P = 0.02;
  const auto f0 = closedForm(P, -0.02);
  continuation::ContinuationOptions o;
  o.from = -0.02, o.to = 0.2, o.tolerance = 1e-12;
  const auto curve = continuation::trackPeak(duffing(false, P), peakPoint(P, f0), f0.w, o);
  ASSERT_TRUE(curve.finished) << curve.stopReason;
  const double err = worstError(curve, false, P);
  std::printf("k3 -0.02 -> 0.2 at force %.3g: %zu points, peak at %.4f -> %.4f rad/s; worst relative error %.2e\n", P,
              curve.points.size(), f0.w, curve.points.back().frequency, err);
  EXPECT_LT(err, 1e-8);
}
