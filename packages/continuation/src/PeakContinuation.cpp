#include "cyclone/continuation/PeakContinuation.hpp"

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

// G and its derivative in the phase at (phi, q), with the centre's solution.
struct Condition {
  double G = 0, dGdphi = 0, measure = 0, w = 0;
  Eigen::VectorXd x;
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
    const ContinuationProblem bordered = borderedAt(w, phi, p, amplitudeOf(x));
    Eigen::VectorXd y(P_.size + 1);
    y << x, 0.0;
    if (!solveNewton(bordered, y, 0.0, o_.tolerance, o_.maxNewtonIterations).converged)
      throw SolverError("peak continuation: no solution at phase " + std::to_string(phi) + " near " +
                        std::to_string(w) + " rad/s, parameter " + std::to_string(p));
    return {y.head(P_.size), w * std::exp(y(P_.size))};
  }

  // Distance between two solved points: a phase change of 0.1 rad weighs as the whole
  // range in q.
  double distance(double phi1, double q1, double phi2, double q2) const {
    return std::hypot((phi1 - phi2) / 0.1, (q1 - q2) / qSpan_);
  }

  // The solution at (phi, q) from `start`: first from the secant through start and the
  // solution made nearest to it (a continuation's steps are long beside the solves'
  // reach on a friction system), then from start itself.
  std::pair<Eigen::VectorXd, double> solveFrom(const Solved& start, double phi, double q) {
    const double p = parameterOf(q);
    const Solved* before = nullptr;
    double bestDistance = std::numeric_limits<double>::infinity();
    for (const auto& s : solved_) {
      const double d = distance(start.phi, start.q, s.phi, s.q);
      if (&s != &start && d > 1e-9 && d < bestDistance) bestDistance = d, before = &s;
    }
    if (before) {
      const double a[2] = {(start.phi - before->phi) / 0.1, (start.q - before->q) / qSpan_};
      const double b[2] = {(phi - start.phi) / 0.1, (q - start.q) / qSpan_};
      const double t = (a[0] * b[0] + a[1] * b[1]) / (a[0] * a[0] + a[1] * a[1]);
      if (t > 1e-6 && t < 4) {
        try {
          return solve(start.x + t * (start.x - before->x), start.w * std::pow(start.w / before->w, t), phi, p);
        } catch (const SolverError&) {
        }
      }
    }
    return solve(start.x, start.w, phi, p);
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

  Condition at(double phi, double q) {
    const double p = parameterOf(q);
    const Solved* start = nearest(phi, q);
    if (!start) throw SolverError("peak continuation: no solution to start from");
    Condition c;
    std::tie(c.x, c.w) = solveFrom(*start, phi, q);
    remember(phi, q, c.w, c.x);
    centres_[{phi, q}] = {c.x, c.w};
    // ln m at phi + {-3, -1, 1, 3} h / 2 and its derivative along the curve there, each
    // side solved from the centre along the curve's tangent.
    const Eigen::VectorXd z = tangent(c.x, c.w, phi, p);
    const double h = o_.phaseStep;
    double L[4], dL[4];
    for (int i = 0; i < 4; ++i) {
      const double u = 0.5 * h * double(2 * i - 3);
      // From the tangent's prediction; where that fails (z from a Jacobian on the other
      // side of a stick-slip corner), from the centre itself.
      std::pair<Eigen::VectorXd, double> side;
      try {
        side = solve(c.x + u * z.head(P_.size), c.w * std::exp(u * z(P_.size)), phi + u, p);
      } catch (const SolverError&) {
        side = solve(c.x, c.w, phi + u, p);
      }
      const double m = P_.measure(side.first);
      if (!(m > 0)) throw SolverError("peak continuation: the response measure is zero (no response to follow)");
      L[i] = std::log(m);
      // d ln m / d phi along the curve at the side: m by a difference along its tangent.
      const Eigen::VectorXd zi = tangent(side.first, side.second, phi + u, p).head(P_.size);
      const double e = 1e-6;
      dL[i] = (std::log(P_.measure(side.first + e * zi)) - std::log(P_.measure(side.first - e * zi))) / (2 * e);
    }
    c.measure = P_.measure(c.x);
    // G is a difference over the sides alone, (L(3h/2) + L(h/2) - L(-h/2) - L(-3h/2)) / 4h:
    // m has sparse kinks (a slope change of 6 in d ln m / d ln w measured on a Jenkins
    // oscillator at 256 samples) and a stencil through the centre, or a narrow one, turned
    // them into jumps of G's slope. Its derivative is this stencil's own (of the sides'
    // slopes), not a second difference of L: at a friction-damped top, flat over less than
    // h, that overstated the slope by 2.4 and LOCA's corrector converged at 0.6 per
    // iteration.
    c.G = (L[3] + L[2] - L[1] - L[0]) / (4 * h);
    c.dGdphi = (dL[3] + dL[2] - dL[1] - dL[0]) / (4 * h);
    return c;
  }

  // d(x, ln w)/d phi along the curve at a solution (the bordered Jacobian there).
  Eigen::VectorXd tangent(const Eigen::VectorXd& x, double w, double phi, double p) const {
    const double amplitude = amplitudeOf(x);
    const ContinuationProblem bordered = borderedAt(w, phi, p, amplitude);
    Eigen::VectorXd y(P_.size + 1);
    y << x, 0.0;
    Eigen::MatrixXd K;
    bordered.jacobian(y, 0.0, K);
    Eigen::VectorXd b = Eigen::VectorXd::Zero(P_.size + 1);
    b(P_.size) = -(x(ic_) * std::cos(phi) + x(is_) * std::sin(phi)) / amplitude;  // -d(condition)/d phi
    Eigen::VectorXd z = DenseLu(K).solve(b);
    if (!z.allFinite()) z.setZero(P_.size + 1);
    return z;
  }

  void remember(double phi, double q, double w, const Eigen::VectorXd& x) {
    solved_.push_back({phi, q, w, x});
    if (solved_.size() > 64) solved_.pop_front();
  }
  // The centre solutions by their exact (phi, q): LOCA's points are where it evaluated G.
  const std::pair<Eigen::VectorXd, double>* centre(double phi, double q) const {
    const auto it = centres_.find({phi, q});
    return it == centres_.end() ? nullptr : &it->second;
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
  std::deque<Solved> solved_;
  std::map<std::pair<double, double>, std::pair<Eigen::VectorXd, double>> centres_;
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
    out.stopReason = "no response at the start (the phase's coefficients are zero)";
    out.seconds = timer.seconds();
    return out;
  }
  const double phiGuess = condition.phaseOf(xStart);
  condition.remember(phiGuess, q0, w0, xStart);
  Condition first;
  if (!condition.peakAt(q0, phiGuess, first)) {
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
    double y = std::numeric_limits<double>::quiet_NaN(), q = 0, G = 0, dGdy = 0;
  };
  auto last = std::make_shared<Last>();
  const auto evaluate = [&condition, last, phiStart](double y, double q) {
    if (!(y == last->y && q == last->q)) {
      const Condition c = condition.at(phiStart + (y - 1), q);
      // F = G / |dG/d phi|: the distance to the peak in phase to first order, so that the
      // tolerance is a phase however sharp or flat the peak.
      const double scale = std::max(std::abs(c.dGdphi), 1e-300);
      *last = {y, q, c.G / scale, c.dGdphi / scale};
    }
  };
  // LOCA's parameter s = q + offset lies in [span, 2 span], so that its difference step
  // for dG/dq (perturbation x |s|) is 0.7e-4 to 1.4e-4 of the range whatever q's value
  // (LOCA's 1e-6 |q| vanishes at q = 0, p = 1): G is continuous but bends where a
  // stick-slip instant crosses a time sample, and a step over such bends gives their
  // mean slope.
  const double span = std::abs(q1 - q0), offset = span - std::min(q0, q1);
  reduced.residual = [evaluate, last, offset](const Eigen::VectorXd& y, double s, Eigen::VectorXd& F) {
    const double q = s - offset;
    evaluate(y(0), q);
    F.resize(1);
    F(0) = last->G;
  };
  reduced.jacobian = [evaluate, last, offset](const Eigen::VectorXd& y, double s, Eigen::MatrixXd& J) {
    const double q = s - offset;
    evaluate(y(0), q);
    J.resize(1, 1);
    J(0, 0) = last->dGdy;
  };
  ContinuationOptions loca;
  loca.engine = ContinuationOptions::Engine::Loca;
  loca.from = q0 + offset, loca.to = q1 + offset;
  loca.locaParameterPerturbation = 7e-5;
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
  out.stopReason = branch.stopReason;
  for (const auto& pt : branch.points) {
    const double phi = phiStart + (pt.x(0) - 1), q = pt.parameter - offset;
    const auto* solved = condition.centre(phi, q);
    if (!solved) {  // not evaluated at exactly this point (never seen): the point is left out
      log::warn("peak continuation: no solution kept at a point of the continuation; left out");
      continue;
    }
    out.points.push_back({condition.parameterOf(q), solved->second, P.measure(solved->first), solved->first, false});
  }
  if (out.points.empty()) out.points.push_back({o.from, first.w, first.measure, first.x, false});

  // The optimum: the smallest peak; inside the range, a golden section in q between its
  // neighbours, each value's peak found from the neighbours' interpolated frequency.
  for (std::size_t i = 0; i < out.points.size(); ++i)
    if (out.optimum < 0 || out.points[i].measure < out.points[std::size_t(out.optimum)].measure) out.optimum = int(i);
  const std::size_t k = std::size_t(out.optimum);
  if (o.locateOptimum && k > 0 && k + 1 < out.points.size()) {
    const auto peakMeasure = [&](double q, FollowedPeak& peak) {
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
      if (!condition.peakAt(q, phi, c)) return false;
      peak = {condition.parameterOf(q), c.w, c.measure, c.x, false};
      return true;
    };
    double a = condition.coordinateOf(out.points[k - 1].parameter), b = condition.coordinateOf(out.points[k + 1].parameter);
    const double golden = 0.5 * (std::sqrt(5.0) - 1);
    double c = b - golden * (b - a), d = a + golden * (b - a);
    FollowedPeak pc, pd;
    bool ok = peakMeasure(c, pc) && peakMeasure(d, pd);
    while (ok && std::abs(b - a) > o.optimumTolerance) {
      if (pc.measure < pd.measure) {
        b = d, d = c, pd = pc, c = b - golden * (b - a);
        ok = peakMeasure(c, pc);
      } else {
        a = c, c = d, pc = pd, d = a + golden * (b - a);
        ok = peakMeasure(d, pd);
      }
    }
    if (ok) {
      const FollowedPeak& best = pc.measure < pd.measure ? pc : pd;
      if (best.measure <= out.points[k].measure) {
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
