#pragma once
// A resonance whose stiffness is piecewise linear in the amplitude, with a kink every
// delta of amplitude (as a sampled contact law has one wherever a contact instant
// crosses a time sample): the stair of kinks the predictor-corrector's secant steps
// cross (test_secant_steps.cpp, test_trace_checkpoint.cpp), with its closed-form peak.
#include <cmath>

#include "cyclone/continuation/ArclengthContinuation.hpp"

namespace cyclone::test_support {

// Triangle wave of period 1, values in [-1, 1], and its slope.
inline double triangle(double s) { return 1 - 4 * std::abs(s - std::floor(s) - 0.5); }
inline double triangleSlope(double s) { return s - std::floor(s) < 0.5 ? 4.0 : -4.0; }

struct KinkedOscillator {
  double m = 1, c = 0.02, k = 1, P = 1;
  // Stiffness k (1 + eps tri(r / delta)), r the amplitude: 5000 kinks up to the peak
  // (r = 50), each turning the tangent where the curve is flat. (With eps 5e-5 the kinks
  // fold the curve into hairpins that neither predictor passes: a wall, said as such.)
  double eps = 2e-5, delta = 0.01;
  double stiffness(double r) const { return k * (1 + eps * triangle(r / delta)); }
  // Single-term harmonic balance, x = a cos + b sin (as SingleTermOscillator.hpp).
  continuation::ContinuationProblem problem() const {
    continuation::ContinuationProblem p;
    p.size = 2;
    const KinkedOscillator o = *this;
    p.residual = [o](const Eigen::VectorXd& x, double W, Eigen::VectorXd& F) {
      const double a = x(0), b = x(1), s = o.stiffness(std::hypot(a, b)) - o.m * W * W;
      F.resize(2);
      F << s * a + o.c * W * b - o.P, s * b - o.c * W * a;
    };
    p.jacobian = [o](const Eigen::VectorXd& x, double W, Eigen::MatrixXd& J) {
      const double a = x(0), b = x(1), r = std::hypot(a, b), s = o.stiffness(r) - o.m * W * W;
      const double dsdr = r > 0 ? o.k * o.eps * triangleSlope(r / o.delta) / o.delta : 0.0;
      const double da = r > 0 ? dsdr * a / r : 0.0, db = r > 0 ? dsdr * b / r : 0.0;
      J.resize(2, 2);
      J << s + a * da, o.c * W + a * db, -o.c * W + b * da, s + b * db;
    };
    p.measure = [](const Eigen::VectorXd& x) { return x.norm(); };
    return p;
  }
  // The largest amplitude of the curve: the first r where r D(r) reaches P, D(r) =
  // min over W of |k_eff(r) - m W^2 + i c W| = c sqrt(k_eff / m - c^2 / (4 m^2)).
  double peakAmplitude() const {
    auto excess = [&](double r) { return r * c * std::sqrt(stiffness(r) / m - c * c / (4 * m * m)) - P; };
    double lo = 0, hi = 0;
    for (double r = 1e-3;; r += 1e-3)
      if (excess(r) > 0) {
        lo = r - 1e-3, hi = r;
        break;
      }
    for (int i = 0; i < 100; ++i) (excess(0.5 * (lo + hi)) > 0 ? hi : lo) = 0.5 * (lo + hi);
    return 0.5 * (lo + hi);
  }
};

}  // namespace cyclone::test_support
