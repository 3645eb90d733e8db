#pragma once
// m x'' + c x' + k x + g x^3 = P cos(W t) by single-term harmonic balance,
// x = a cos + b sin, whose force terms are closed-form:
//   (k - m W^2) a + c W b + 3/4 g (a^2 + b^2) a = P,  (k - m W^2) b - c W a + 3/4 g (a^2 + b^2) b = 0.
#include "cyclone/continuation/ArclengthContinuation.hpp"

namespace cyclone::test_support {

inline continuation::ContinuationProblem singleTermOscillator(double m, double c, double k, double g, double P) {
  continuation::ContinuationProblem p;
  p.size = 2;
  p.residual = [=](const Eigen::VectorXd& x, double W, Eigen::VectorXd& F) {
    const double a = x(0), b = x(1), s = k - m * W * W + 0.75 * g * (a * a + b * b);
    F.resize(2);
    F << s * a + c * W * b - P, s * b - c * W * a;
  };
  p.jacobian = [=](const Eigen::VectorXd& x, double W, Eigen::MatrixXd& J) {
    const double a = x(0), b = x(1), s = k - m * W * W + 0.75 * g * (a * a + b * b);
    J.resize(2, 2);
    J << s + 1.5 * g * a * a, c * W + 1.5 * g * a * b, -c * W + 1.5 * g * a * b, s + 1.5 * g * b * b;
  };
  return p;
}

}  // namespace cyclone::test_support
