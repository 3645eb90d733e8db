#include "cyclone/continuation/PeakContinuation.hpp"

#include "GoldenSection.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <map>
#include <utility>
#include <limits>
#include <sstream>
#include <tuple>

#include "cyclone/continuation/DenseLu.hpp"
#include "cyclone/continuation/NewtonSolve.hpp"
#include "cyclone/core/Error.hpp"
#include "cyclone/core/Log.hpp"
#include "cyclone/core/Timer.hpp"

namespace cyclone::continuation {

namespace {

// A solution of the system: x at the frequency w, phase phi and parameter coordinate q.
struct Solved {
  double phi = 0, q = 0, w = 0;
  Eigen::VectorXd x;
};

// A solution at phase phi with ln m there and its derivative along the curve.
struct Slope {
  double phi = 0, L = 0, dL = 0, dLdq = 0, w = 0;
  Eigen::VectorXd x, z;  // the solution and the curve's tangent d(x, ln w)/d phi there
};

// G and its derivative in the phase at (phi, q), from the sides phi -+ h.
struct Condition {
  double G = 0, dGdphi = 0, dGdq = 0;
  Slope minus, plus;
};

class ReducedPeakCondition {
public:
  ReducedPeakCondition(const PeakTrackingProblem& P, const PeakContinuationOptions& o, FollowedPeakCurve& out)
      : P_(P), o_(o), out_(out), ic_(P.phaseCosIndex), is_(P.phaseSinIndex) {}

  double parameterOf(double q) const { return o_.logarithmic ? std::exp(q) : q; }
  double coordinateOf(double p) const { return o_.logarithmic ? std::log(p) : p; }
  double phaseOf(const Eigen::VectorXd& x) const { return std::atan2(x(is_), x(ic_)); }

  // The solution at phase phi and parameter p: x and w by Newton on R(x, w; p) = 0 with
  // the phase condition (x_c sin phi - x_s cos phi) / A = 0, A the start's amplitude (a
  // phase error in radians), unknowns (x, ln(w / w_start)); NewtonSolve's backtracking,
  // no stall test (near a stick-slip corner Newton can take many slow iterations before
  // it settles on a piece, and a solve given up there stopped the continuation). Throws
  // where it does not converge (a failed evaluation: LOCA cuts its step).
  std::pair<Eigen::VectorXd, double> solve(const Eigen::VectorXd& x, double w, double phi, double p) {
    ++out_.solves;
    lastAmplitude_ = amplitudeOf(x);
    const ContinuationProblem bordered = borderedAt(w, phi, p, lastAmplitude_);
    Eigen::VectorXd y(P_.size + 1);
    y << x, 0.0;
    const NewtonResult r = solveNewton(bordered, y, 0.0, o_.tolerance, o_.maxNewtonIterations, &lastFactors_);
    lastIterations_ = r.iterations;
    if (!r.converged)
      throw SolverError("peak continuation: no solution at phase " + std::to_string(phi) + " near " +
                        std::to_string(w) + " rad/s, parameter " + std::to_string(p));
    return {y.head(P_.size), w * std::exp(y(P_.size))};
  }

  // Distance between two solved points: a phase change of 0.1 rad weighs as the whole
  // range in q.
  double distance(double phi1, double q1, double phi2, double q2) const {
    return std::hypot((phi1 - phi2) / 0.1, (q1 - q2) / qSpan_);
  }

  // The solution at (phi, q) from the nearest solution made so far: first from the
  // secant through it and the solution nearest to that (a continuation's steps are long
  // beside the solves' reach on a friction system), then from it; where both fail, the
  // midpoint first (to a depth of 4 halvings), each solution kept.
  std::pair<Eigen::VectorXd, double> solveFromNearest(double phi, double q, int depth = 0) {
    const Solved* start = nearest(phi, q);
    if (!start) throw SolverError("peak continuation: no solution to start from");
    const double p = parameterOf(q);
    const Solved* before = nullptr;
    double bestDistance = std::numeric_limits<double>::infinity();
    for (const auto& s : solved_) {
      const double d = distance(start->phi, start->q, s.phi, s.q);
      if (&s != start && d > 1e-9 && d < bestDistance) bestDistance = d, before = &s;
    }
    if (before) {
      const double a[2] = {(start->phi - before->phi) / 0.1, (start->q - before->q) / qSpan_};
      const double b[2] = {(phi - start->phi) / 0.1, (q - start->q) / qSpan_};
      const double t = (a[0] * b[0] + a[1] * b[1]) / (a[0] * a[0] + a[1] * a[1]);
      if (t > 1e-6 && t < 4) {
        try {
          return solve(start->x + t * (start->x - before->x), start->w * std::pow(start->w / before->w, t), phi, p);
        } catch (const SolverError&) {
        }
      }
    }
    try {
      return solve(start->x, start->w, phi, p);
    } catch (const SolverError&) {
      if (depth >= 4 || distance(phi, q, start->phi, start->q) < 1e-6) throw;
    }
    const double midPhi = 0.5 * (phi + start->phi), midQ = 0.5 * (q + start->q);
    const auto mid = solveFromNearest(midPhi, midQ, depth + 1);
    remember(midPhi, midQ, mid.second, mid.first);
    return solveFromNearest(phi, q, depth + 1);
  }

  // The nearest solution made so far: where a solve at (phi, q) starts.
  const Solved* nearest(double phi, double q) const {
    const Solved* best = nullptr;
    double bestDistance = std::numeric_limits<double>::infinity();
    for (const auto& s : solved_) {
      const double d = distance(phi, q, s.phi, s.q);
      if (d < bestDistance) bestDistance = d, best = &s;
    }
    return best;
  }

  // ln m at (phi, q) and d ln m / d phi along the curve there (m by a difference along
  // the curve's tangent). `from`: a solution near phi at the same q, whose tangent is the
  // predictor (else the nearest solution made).
  Slope slopeAt(double phi, double q, const Slope* from = nullptr) {
    const double p = parameterOf(q);
    Slope s;
    s.phi = phi;
    bool solved = false;
    if (from) {
      const double u = phi - from->phi;
      try {
        std::tie(s.x, s.w) = solve(from->x + u * from->z.head(P_.size), from->w * std::exp(u * from->z(P_.size)), phi, p);
        solved = true;
      } catch (const SolverError&) {  // the prediction from a Jacobian beyond a stick-slip corner
      }
    }
    if (!solved) std::tie(s.x, s.w) = solveFromNearest(phi, q);
    remember(phi, q, s.w, s.x);
    const double m = P_.measure(s.x);
    if (!(m > 0)) throw SolverError("peak continuation: the response measure is zero (no response to follow)");
    s.L = std::log(m);
    // The tangent by the LU of Newton's last iteration (the bordered Jacobian one step
    // before the solution: the slope it gives is LOCA's Jacobian and the other side's
    // predictor, neither of which needs it exact), else by the Jacobian at the solution.
    if (lastIterations_ == 0) factorBordered(s.x, s.w, phi, p, lastFactors_);
    s.z = tangentBy(lastFactors_, s.x, phi);  // the factors' phase row scaled by lastAmplitude_
    const double e = 1e-6;
    const auto slopeAlong = [&](const Eigen::VectorXd& d) {
      return (std::log(P_.measure(s.x + e * d)) - std::log(P_.measure(s.x - e * d))) / (2 * e);
    };
    s.dL = slopeAlong(s.z.head(P_.size));
    // d ln m / dq at a fixed phase (the same factors, R's derivative in q by a central
    // difference): LOCA's dG/dq, which it would otherwise take as a difference of G.
    const double dq = o_.logarithmic ? e : e * qSpan_;
    Eigen::VectorXd Rp, Rm;
    P_.residual(s.x, s.w, parameterOf(q + dq), Rp);
    P_.residual(s.x, s.w, parameterOf(q - dq), Rm);
    Eigen::VectorXd b = Eigen::VectorXd::Zero(P_.size + 1);
    b.head(P_.size) = -(Rp - Rm) / (2 * dq);
    const Eigen::VectorXd zq = lastFactors_.solve(b);
    s.dLdq = zq.allFinite() ? slopeAlong(zq.head(P_.size)) : 0.0;
    return s;
  }

  // G = (L(phi + h) - L(phi - h)) / 2h and its derivative, the stencil's own (of the
  // sides' slopes): a difference over the sides spans the sparse kinks of m (a slope
  // change of 6 in d ln m / d ln w on a Jenkins oscillator at 256 samples), where a
  // narrow or a centred stencil turned them into jumps of G's slope; and the slope as a
  // second difference of L overstated it by 2.4 at a friction-damped top flat over less
  // than h, so that LOCA's corrector converged at 0.6 per iteration.
  Condition at(double phi, double q) {
    const double h = o_.phaseStep;
    Condition c;
    c.minus = slopeAt(phi - h, q);
    c.plus = slopeAt(phi + h, q, &c.minus);
    c.G = (c.plus.L - c.minus.L) / (2 * h);
    c.dGdphi = (c.plus.dL - c.minus.dL) / (2 * h);
    c.dGdq = (c.plus.dLdq - c.minus.dLdq) / (2 * h);
    return c;
  }

  // The solution at G's zero (phi, q), from the sides of its evaluation when given.
  // Not the maximum of m between the sides: at low preloads the disc's top is a chain of
  // micro-folds (a contact event crossing a time sample at each), a local maximum every
  // 0.03-0.1 Hz and 1e-3 apart in m, and the maximum between the sides was one of those
  // teeth; G's zero is the peak of their envelope.
  FollowedPeak peakPoint(double phi, double q, const Condition* sides = nullptr) {
    std::pair<Eigen::VectorXd, double> c;
    bool solved = false;
    if (sides) {
      const Slope& from = sides->minus;
      const double u = phi - from.phi;
      try {
        c = solve(from.x + u * from.z.head(P_.size), from.w * std::exp(u * from.z(P_.size)), phi, parameterOf(q));
        solved = true;
      } catch (const SolverError&) {
      }
    }
    if (!solved) c = solveFromNearest(phi, q);
    remember(phi, q, c.second, c.first);
    return FollowedPeak{parameterOf(q), c.second, P_.measure(c.first), c.first, false};
  }

  // The bordered Jacobian at a solution, factored.
  void factorBordered(const Eigen::VectorXd& x, double w, double phi, double p, DenseLu& factors) {
    lastAmplitude_ = amplitudeOf(x);
    const ContinuationProblem bordered = borderedAt(w, phi, p, lastAmplitude_);
    Eigen::VectorXd y(P_.size + 1);
    y << x, 0.0;
    Eigen::MatrixXd K;
    bordered.jacobian(y, 0.0, K);
    factors.computeTaking(K);
  }

  // d(x, ln w)/d phi along the curve at a solution, by factors of the bordered Jacobian
  // (its phase row divided by lastAmplitude_, as the right-hand side here).
  Eigen::VectorXd tangentBy(const DenseLu& factors, const Eigen::VectorXd& x, double phi) const {
    Eigen::VectorXd b = Eigen::VectorXd::Zero(P_.size + 1);
    b(P_.size) = -(x(ic_) * std::cos(phi) + x(is_) * std::sin(phi)) / lastAmplitude_;
    Eigen::VectorXd z = factors.solve(b);
    if (!z.allFinite()) z.setZero(P_.size + 1);
    return z;
  }

  void remember(double phi, double q, double w, const Eigen::VectorXd& x) {
    solved_.push_back({phi, q, w, x});
    if (solved_.size() > 64) solved_.pop_front();
  }

  // The peak at q from phase phi: Newton on G in phi.
  bool peakAt(double q, double phi, Condition& c) {
    for (int it = 0; it < 30; ++it) {
      try {
        c = at(phi, q);
      } catch (const SolverError&) {
        return false;
      }
      if (std::abs(c.G) <= o_.conditionTolerance * std::abs(c.dGdphi)) {
        lastPeakPhase_ = phi;
        return true;
      }
      if (!(c.dGdphi < 0)) return false;  // not near a maximum
      phi += std::clamp(-c.G / c.dGdphi, -0.3, 0.3);
    }
    return false;
  }

  void setSpan(double qSpan) { qSpan_ = std::max(qSpan, 1e-12); }
  double lastPeakPhase() const { return lastPeakPhase_; }

private:
  double amplitudeOf(const Eigen::VectorXd& x) const {
    const double a = std::hypot(x(ic_), x(is_));
    if (!(a > 0)) throw SolverError("peak continuation: the phase's coefficients are zero (no response to follow)");
    return a;
  }

  // R(x, w; p) and the phase condition in y = (x, ln(w / w0)), at the phase phi.
  ContinuationProblem borderedAt(double w0, double phi, double p, double amplitude) const {
    const int n = P_.size, ic = ic_, is = is_;
    const double sn = std::sin(phi) / amplitude, cs = std::cos(phi) / amplitude;
    ContinuationProblem B;
    B.size = n + 1;
    const PeakTrackingProblem& P = P_;
    B.residual = [&P, n, ic, is, sn, cs, w0, p](const Eigen::VectorXd& y, double, Eigen::VectorXd& F) {
      Eigen::VectorXd R;
      P.residual(y.head(n), w0 * std::exp(y(n)), p, R);
      F.resize(n + 1);
      F.head(n) = R;
      F(n) = y(ic) * sn - y(is) * cs;
    };
    B.jacobian = [&P, n, ic, is, sn, cs, w0, p](const Eigen::VectorXd& y, double, Eigen::MatrixXd& K) {
      const Eigen::VectorXd x = y.head(n);
      const double w = w0 * std::exp(y(n));
      Eigen::MatrixXd J;
      P.jacobian(x, w, p, J);
      // w dR/dw by a central difference: R is linear in w's powers at a fixed x (the
      // contact forces of a harmonic balance depend on x alone), so 1e-6 is exact to
      // rounding.
      const double e = 1e-6;
      Eigen::VectorXd Rp, Rm;
      P.residual(x, w * (1 + e), p, Rp);
      P.residual(x, w * (1 - e), p, Rm);
      K.setZero(n + 1, n + 1);
      K.topLeftCorner(n, n) = J;
      K.col(n).head(n) = (Rp - Rm) / (2 * e);
      K(n, ic) = sn;
      K(n, is) = -cs;
    };
    return B;
  }

  const PeakTrackingProblem& P_;
  const PeakContinuationOptions& o_;
  FollowedPeakCurve& out_;
  const int ic_, is_;
  DenseLu lastFactors_;     // the last solve's last Newton LU
  int lastIterations_ = 0;  // and its iterations (0: no LU made)
  double lastAmplitude_ = 1;  // the amplitude its phase row was divided by
  std::deque<Solved> solved_;
  double qSpan_ = 1, lastPeakPhase_ = 0;
};

}  // namespace

FollowedPeakCurve continuePeak(const PeakTrackingProblem& P, const Eigen::VectorXd& x0, double w0,
                               const PeakContinuationOptions& o) {
  if (P.size < 1 || !P.residual || !P.jacobian || !P.measure)
    throw InputError("peak continuation", "the problem needs its size, residual, Jacobian and measure");
  if (x0.size() != P.size) throw InputError("peak continuation", "the start's size differs from the problem's");
  if (!(w0 > 0) || !std::isfinite(w0)) throw InputError("peak continuation", "the start's frequency must be > 0");
  if (!(std::isfinite(o.from) && std::isfinite(o.to) && o.from != o.to))
    throw InputError("peak continuation", "the range needs from != to");
  if (o.logarithmic && !(o.from > 0 && o.to > 0))
    throw InputError("peak continuation", "a logarithmic range needs from > 0 and to > 0");
  if (P.phaseCosIndex < 0 || P.phaseSinIndex < 0 || P.phaseCosIndex >= P.size || P.phaseSinIndex >= P.size ||
      P.phaseCosIndex == P.phaseSinIndex)
    throw InputError("peak continuation", "the problem needs the phase's cos and sin coefficients (phaseCosIndex, phaseSinIndex)");
  if (!(o.phaseStep > 0 && o.phaseStep < 0.5)) throw InputError("peak continuation", "phaseStep must lie in (0, 0.5) rad");
  Timer timer;
  FollowedPeakCurve out;
  ReducedPeakCondition condition(P, o, out);
  const double q0 = condition.coordinateOf(o.from), q1 = condition.coordinateOf(o.to);
  condition.setSpan(std::abs(q1 - q0));

  // The start solved at w0, its phase the first guess of the peak's; the peak at the
  // start, then LOCA on G(phi; q) = 0 in y = 1 + phi - phi_start.
  Eigen::VectorXd xStart = x0;
  {
    ContinuationProblem atW0;
    atW0.size = P.size;
    atW0.residual = [&P, w0](const Eigen::VectorXd& y, double p, Eigen::VectorXd& R) { P.residual(y, w0, p, R); };
    atW0.jacobian = [&P, w0](const Eigen::VectorXd& y, double p, Eigen::MatrixXd& J) { P.jacobian(y, w0, p, J); };
    ++out.solves;
    if (!solveNewton(atW0, xStart, o.from, o.tolerance, o.maxNewtonIterations).converged) xStart = x0;
  }
  if (!(std::hypot(xStart(P.phaseCosIndex), xStart(P.phaseSinIndex)) > 0)) {
    out.end = PeakFollowingEnd::NoPeakAtStart;
    out.stopReason = "no response at the start (the phase's coefficients are zero)";
    out.seconds = timer.seconds();
    return out;
  }
  const double phiGuess = condition.phaseOf(xStart);
  condition.remember(phiGuess, q0, w0, xStart);
  Condition first;
  if (!condition.peakAt(q0, phiGuess, first)) {
    out.end = PeakFollowingEnd::NoPeakAtStart;
    out.stopReason = "no peak found near " + std::to_string(w0) + " rad/s at the start of the range";
    out.seconds = timer.seconds();
    return out;
  }
  const double phiStart = condition.lastPeakPhase();
  ContinuationProblem reduced;
  reduced.size = 1;
  // G and dG/dy at the last (y, q) evaluated: LOCA asks for the Jacobian where it has
  // just had the residual.
  struct Last {
    double y = std::numeric_limits<double>::quiet_NaN(), q = 0, G = 0, dGdy = 0, dGdq = 0;
  };
  auto last = std::make_shared<Last>();
  // The sides of every evaluation by its exact (phi, q): LOCA's points are where it
  // evaluated G, and each is solved again at its G's zero from its sides.
  auto evaluated = std::make_shared<std::map<std::pair<double, double>, Condition>>();
  const auto evaluate = [&condition, last, evaluated, phiStart](double y, double q) {
    if (!(y == last->y && q == last->q)) {
      const Condition c = condition.at(phiStart + (y - 1), q);
      (*evaluated)[{phiStart + (y - 1), q}] = c;
      // F = G / |dG/d phi|: the distance to the peak in phase to first order, so that the
      // tolerance is a phase however sharp or flat the peak.
      const double scale = std::max(std::abs(c.dGdphi), 1e-300);
      *last = {y, q, c.G / scale, c.dGdphi / scale, c.dGdq / scale};
    }
  };
  // LOCA continues in q itself; its dF/dq is the sides' (parameterDerivative), not a
  // difference of G in q.
  reduced.residual = [evaluate, last](const Eigen::VectorXd& y, double q, Eigen::VectorXd& F) {
    evaluate(y(0), q);
    F.resize(1);
    F(0) = last->G;
  };
  reduced.jacobian = [evaluate, last](const Eigen::VectorXd& y, double q, Eigen::MatrixXd& J) {
    evaluate(y(0), q);
    J.resize(1, 1);
    J(0, 0) = last->dGdy;
  };
  reduced.parameterDerivative = [evaluate, last](const Eigen::VectorXd& y, double q, Eigen::VectorXd& d) {
    evaluate(y(0), q);
    d.resize(1);
    d(0) = last->dGdq;
  };
  ContinuationOptions loca;
  loca.engine = ContinuationOptions::Engine::Loca;
  loca.from = q0, loca.to = q1;
  loca.tolerance = o.conditionTolerance;
  loca.initialStep = o.initialStep;
  loca.minStep = o.minStep;
  loca.maxStep = o.maxStep > 0 ? o.maxStep : std::abs(q1 - q0) / 12;
  loca.maxSteps = o.maxSteps;
  loca.maxNewtonIterations = 12;
  // LOCA's arclength rescaling kept the steps at a few 1e-3 of the unknown (400 steps
  // for the Jenkins oscillator's range, unfinished); the phase and q are both of order one.
  loca.arcLengthScaling = false;
  const Branch branch = traceBranch(reduced, Eigen::VectorXd::Constant(1, 1.0), loca);
  out.searches = int(branch.points.size());
  out.complete = branch.finished;
  out.end = branch.finished ? PeakFollowingEnd::RangeEnd : PeakFollowingEnd::ContinuationStopped;
  out.branchEnd = branch.end;
  out.stopReason = branch.stopReason;
  // Each of LOCA's points solved at its G's zero.
  int unsolved = 0;
  for (const auto& pt : branch.points) {
    const double phi = phiStart + (pt.x(0) - 1), q = pt.parameter;
    const auto it = evaluated->find({phi, q});
    try {
      out.points.push_back(condition.peakPoint(phi, q, it == evaluated->end() ? nullptr : &it->second));
    } catch (const SolverError&) {  // left out, said
      ++unsolved;
    }
  }
  if (unsolved > 0)
    log::warn("peak continuation: " + std::to_string(unsolved) + " of LOCA's points not solved again; left out");
  if (out.points.empty()) out.points.push_back(condition.peakPoint(phiStart, q0, &first));

  // The optimum: the smallest peak; inside the range, a golden section in q between its
  // neighbours, each value's peak found from the neighbours' interpolated frequency.
  for (std::size_t i = 0; i < out.points.size(); ++i)
    if (out.optimum < 0 || out.points[i].measure < out.points[std::size_t(out.optimum)].measure) out.optimum = int(i);
  const std::size_t k = std::size_t(out.optimum);
  if (o.locateOptimum && k > 0 && k + 1 < out.points.size()) {
    const auto peakMeasure = [&](double q, const FollowedPeak&, const FollowedPeak&) -> std::optional<FollowedPeak> {
      // The traced peak's phase, interpolated in q, as the start.
      double phi = condition.phaseOf(out.points[k].x);
      for (std::size_t i = 0; i + 1 < out.points.size(); ++i) {
        const double qa = condition.coordinateOf(out.points[i].parameter), qb = condition.coordinateOf(out.points[i + 1].parameter);
        if ((q - qa) * (q - qb) <= 0 && qa != qb) {
          const double pa = condition.phaseOf(out.points[i].x),
                       pb = pa + std::remainder(condition.phaseOf(out.points[i + 1].x) - pa, 2 * M_PI);
          phi = pa + (q - qa) / (qb - qa) * (pb - pa);
          break;
        }
      }
      Condition c;
      if (!condition.peakAt(q, phi, c)) return std::nullopt;
      try {
        return condition.peakPoint(condition.lastPeakPhase(), q, &c);
      } catch (const SolverError&) {
        return std::nullopt;
      }
    };
    const auto located = detail::goldenSection(
        out.points[k - 1], out.points[k], out.points[k + 1], o.optimumTolerance,
        [&](const FollowedPeak& p) { return condition.coordinateOf(p.parameter); }, peakMeasure,
        [](const FollowedPeak& a, const FollowedPeak& b) { return a.measure < b.measure; });
    if (located) {
      const FollowedPeak& best = *located;
      if (best.measure < out.points[k].measure) {  // else the grid's point is the optimum to the tolerance
        // Into the curve in its order of tracing (between k's neighbours).
        const double qb = condition.coordinateOf(best.parameter), qk = condition.coordinateOf(out.points[k].parameter),
                     qNext = condition.coordinateOf(out.points[k + 1].parameter);
        const std::size_t at = (qb - qk) * (qNext - qk) > 0 ? k + 1 : k;
        out.points.insert(out.points.begin() + std::ptrdiff_t(at), best);
        out.optimum = int(at);
      }
      out.optimumLocated = true;
    }
  }
  out.seconds = timer.seconds();
  std::ostringstream msg;
  msg << "peak continuation (LOCA on the peak condition): " << out.points.size() << " peaks over "
      << condition.parameterOf(q0) << " .. " << condition.parameterOf(q1) << ", " << out.solves
      << " solves, " << out.seconds << " s" << (out.complete ? "" : "; stopped: " + out.stopReason);
  log::info(msg.str());
  return out;
}

}  // namespace cyclone::continuation
