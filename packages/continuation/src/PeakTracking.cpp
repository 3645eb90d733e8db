#include "cyclone/continuation/PeakTracking.hpp"

#include <algorithm>
#include <cmath>

#include "cyclone/continuation/DenseLu.hpp"
#include "cyclone/core/Error.hpp"

namespace cyclone::continuation {

namespace {

// The pieces at (x, w; p): the residual, J, dR/dw, the tangent z, lambda and g.
struct PeakState {
  Eigen::VectorXd R, Rp, Rm, Rw, z, lambda, gradient;  // Rp, Rm: R at w +- frequencyStep(w)
  Eigen::MatrixXd J;
  double m = 0, g = 0;
};

double frequencyStep(double w) { return 1e-6 * std::max(std::abs(w), 1e-8); }

PeakState evaluate(const PeakTrackingProblem& P, const Eigen::VectorXd& x, double w, double p, bool withLambda) {
  PeakState s;
  P.residual(x, w, p, s.R);
  P.jacobian(x, w, p, s.J);
  const double d = frequencyStep(w);
  P.residual(x, w + d, p, s.Rp);
  P.residual(x, w - d, p, s.Rm);
  s.Rw = (s.Rp - s.Rm) / (2 * d);
  DenseLu lu(s.J);
  s.z = -lu.solve(s.Rw);
  s.m = P.measure(x);
  s.gradient = P.measureGradient(x);
  if (!(s.m > 0)) throw SolverError("peak tracking: the response measure is zero (no response to follow)");
  s.g = w / s.m * s.gradient.dot(s.z);
  if (withLambda) s.lambda = lu.solveTransposed(s.gradient);
  return s;
}

// The solution of R(., w; p) = 0 nearest x by Newton (throws when it does not converge).
Eigen::VectorXd solutionAt(const PeakTrackingProblem& P, Eigen::VectorXd x, double w, double p) {
  Eigen::VectorXd R;
  Eigen::MatrixXd J;
  P.residual(x, w, p, R);
  const double scale = 1 + R.norm();
  for (int it = 0; it < 30; ++it) {
    P.jacobian(x, w, p, J);
    x -= DenseLu(J).solve(R);
    P.residual(x, w, p, R);
    if (!R.allFinite()) break;
    if (R.norm() <= 1e-13 * scale) return x;
  }
  throw SolverError("peak tracking: no solution at a neighbouring frequency");
}

// g of the solutions at w (1 +- h): the log-slope of m along the curve, continuous.
double slopeBySolutions(const PeakTrackingProblem& P, const Eigen::VectorXd& x, double w, double p) {
  const double h = P.solutionStep;
  const double mp = P.measure(solutionAt(P, x, w * (1 + h), p)), mm = P.measure(solutionAt(P, x, w * (1 - h), p));
  const double m0 = 0.5 * (mp + mm);
  if (!(m0 > 0)) throw SolverError("peak tracking: the response measure is zero (no response to follow)");
  return (mp - mm) / (2 * h * m0);
}

}  // namespace

ContinuationProblem peakCondition(const PeakTrackingProblem& P) {
  if (P.size < 1 || !P.residual || !P.jacobian || !P.measure || !P.measureGradient || !P.measureHessianTimes)
    throw InputError("peak tracking", "the problem needs its size, residual, Jacobian and measure with derivatives");
  ContinuationProblem out;
  out.size = P.size + 1;
  if (!P.scaleGroups.empty()) {  // the frequency unknown in a group of its own
    out.scaleGroups = P.scaleGroups;
    out.scaleGroups.push_back(*std::max_element(P.scaleGroups.begin(), P.scaleGroups.end()) + 1);
  }
  const int n = P.size;
  const double unit = P.frequencyUnit;
  if (P.solutionStep > 0) {
    out.residual = [P, n, unit](const Eigen::VectorXd& y, double p, Eigen::VectorXd& F) {
      const Eigen::VectorXd x = y.head(n);
      Eigen::VectorXd R;
      P.residual(x, unit * y(n), p, R);
      F.resize(n + 1);
      F.head(n) = R;
      F(n) = slopeBySolutions(P, x, unit * y(n), p);
    };
    out.jacobian = [P, n, unit](const Eigen::VectorXd& y, double p, Eigen::MatrixXd& Jy) {
      const Eigen::VectorXd x = y.head(n);
      const double w = unit * y(n), d = 2 * P.solutionStep * w;
      Eigen::MatrixXd J;
      P.jacobian(x, w, p, J);
      Eigen::VectorXd Rp, Rm;
      P.residual(x, w + frequencyStep(w), p, Rp);
      P.residual(x, w - frequencyStep(w), p, Rm);
      Jy = Eigen::MatrixXd::Zero(n + 1, n + 1);
      Jy.topLeftCorner(n, n) = J;
      Jy.topRightCorner(n, 1) = unit * (Rp - Rm) / (2 * frequencyStep(w));
      Jy(n, n) = unit * (slopeBySolutions(P, x, w + d, p) - slopeBySolutions(P, x, w - d, p)) / (2 * d);
    };
    out.measure = [P, n](const Eigen::VectorXd& y) { return P.measure(Eigen::VectorXd(y.head(n))); };
    return out;
  }
  out.residual = [P, n, unit](const Eigen::VectorXd& y, double p, Eigen::VectorXd& F) {
    const Eigen::VectorXd x = y.head(n);
    const auto s = evaluate(P, x, unit * y(n), p, false);
    F.resize(n + 1);
    F.head(n) = s.R;
    F(n) = s.g;
  };
  out.jacobian = [P, n, unit](const Eigen::VectorXd& y, double p, Eigen::MatrixXd& Jy) {
    const Eigen::VectorXd x = y.head(n);
    const double w = unit * y(n);
    const auto s = evaluate(P, x, w, p, true);
    // lambda . (dJ/dx_i) z and lambda . d(dR/dw)/dx_i by the symmetry of second derivatives.
    const double eps = 1e-7 * (1 + x.norm()) / std::max(s.z.norm(), 1e-300);
    Eigen::MatrixXd Jz, Jw;
    P.jacobian(x + eps * s.z, w, p, Jz);
    const double d = frequencyStep(w);
    P.jacobian(x, w + d, p, Jw);
    const Eigen::VectorXd JTl = s.J.transpose() * s.lambda;
    const Eigen::VectorXd lambdaDJz = (Jz.transpose() * s.lambda - JTl) / eps;
    const Eigen::VectorXd lambdaDRw = (Jw.transpose() * s.lambda - JTl) / d;
    // d(grad m . z)/dx = H z - (lambda . dJ z + lambda . dRw/dx).
    const Eigen::VectorXd dGdx = P.measureHessianTimes(x, s.z) - lambdaDJz - lambdaDRw;
    // d(grad m . z)/dw = -lambda . (dJ/dw z + d2R/dw2).
    const Eigen::VectorXd Rww = (s.Rp - 2 * s.R + s.Rm) / (d * d);  // the same step as evaluate's
    const double dGdw = -s.lambda.dot((Jw - s.J) * s.z / d + Rww);
    // g = (w / m) G, G = grad m . z.
    const double G = s.gradient.dot(s.z);
    Jy.resize(n + 1, n + 1);
    Jy.topLeftCorner(n, n) = s.J;
    Jy.topRightCorner(n, 1) = unit * s.Rw;
    Jy.bottomLeftCorner(1, n) = (w / s.m * dGdx - w * G / (s.m * s.m) * s.gradient).transpose();
    Jy(n, n) = unit * (w / s.m * dGdw + G / s.m);
  };
  out.measure = [P, n](const Eigen::VectorXd& y) { return P.measure(Eigen::VectorXd(y.head(n))); };
  return out;
}

void useSquaredAmplitude(PeakTrackingProblem& P, int c, int s) {
  P.phaseCosIndex = c, P.phaseSinIndex = s;
  P.measure = [c, s](const Eigen::VectorXd& x) { return x(c) * x(c) + x(s) * x(s); };
  P.measureGradient = [c, s](const Eigen::VectorXd& x) {
    Eigen::VectorXd g = Eigen::VectorXd::Zero(x.size());
    g(c) = 2 * x(c), g(s) = 2 * x(s);
    return g;
  };
  P.measureHessianTimes = [c, s](const Eigen::VectorXd& x, const Eigen::VectorXd& v) {
    Eigen::VectorXd h = Eigen::VectorXd::Zero(x.size());
    h(c) = 2 * v(c), h(s) = 2 * v(s);
    return h;
  };
}

PeakCurve trackPeak(const PeakTrackingProblem& P, const Eigen::VectorXd& x0, double w0,
                    const ContinuationOptions& options) {
  const auto extended = peakCondition(P);
  Eigen::VectorXd y0(P.size + 1);
  y0.head(P.size) = x0;
  y0(P.size) = w0 / P.frequencyUnit;
  const auto branch = traceBranch(extended, y0, options);
  PeakCurve out;
  out.finished = branch.finished;
  out.end = branch.end;
  out.stopReason = branch.stopReason;
  out.statistics = branch.statistics;
  for (const auto& pt : branch.points) {
    TrackedPeak t;
    t.parameter = pt.parameter;
    t.x = pt.x.head(P.size);
    t.frequency = P.frequencyUnit * pt.x(P.size);
    t.measure = P.measure(t.x);
    out.points.push_back(std::move(t));
  }
  return out;
}

}  // namespace cyclone::continuation
