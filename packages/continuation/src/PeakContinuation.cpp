#include "cyclone/continuation/PeakContinuation.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <map>
#include <utility>
#include <limits>
#include <sstream>

#include "cyclone/continuation/DenseLu.hpp"
#include "cyclone/continuation/NewtonSolve.hpp"
#include "cyclone/core/Error.hpp"
#include "cyclone/core/Log.hpp"
#include "cyclone/core/Timer.hpp"

namespace cyclone::continuation {

namespace {

// A solution of the system at (w, p).
struct Solved {
  double lnw = 0, q = 0;
  Eigen::VectorXd x;
};

// G and its derivative in ln w at (w, q), with the centre's solution.
struct Condition {
  double G = 0, dGdlnw = 0, measure = 0;
  Eigen::VectorXd x;
};

class ReducedPeakCondition {
public:
  ReducedPeakCondition(const PeakTrackingProblem& P, const PeakContinuationOptions& o, FollowedPeakCurve& out)
      : P_(P), o_(o), out_(out) {}

  double parameterOf(double q) const { return o_.logarithmic ? std::exp(q) : q; }
  double coordinateOf(double p) const { return o_.logarithmic ? std::log(p) : p; }

  // The solution at (w, p) by Newton from x (NewtonSolve: backtracking, no stall test:
  // near a stick-slip corner Newton can take many slow iterations before it settles on a
  // piece, and a solve given up there stopped the continuation). Throws where it does not
  // converge (a failed evaluation: LOCA cuts its step).
  Eigen::VectorXd solve(Eigen::VectorXd x, double w, double p) {
    ++out_.solves;
    ContinuationProblem atP;  // in w, at p
    atP.size = P_.size;
    atP.residual = [this, p](const Eigen::VectorXd& y, double wy, Eigen::VectorXd& R) { P_.residual(y, wy, p, R); };
    atP.jacobian = [this, p](const Eigen::VectorXd& y, double wy, Eigen::MatrixXd& J) { P_.jacobian(y, wy, p, J); };
    if (!solveNewton(atP, x, w, o_.tolerance, o_.maxNewtonIterations).converged)
      throw SolverError("peak continuation: no solution at " + std::to_string(w) + " rad/s, parameter " +
                        std::to_string(p));
    return x;
  }

  // Distance between two solved points: a relative frequency change of 1 % weighs as the
  // whole range in q.
  double distance(double lnw1, double q1, double lnw2, double q2) const {
    return std::hypot((lnw1 - lnw2) / 0.01, (q1 - q2) / qSpan_);
  }

  // The solution at (ln w, q) from `start`: first from the secant through start and the
  // solution made nearest to it (a continuation's steps are long beside the solves'
  // reach on a friction system), then from start itself.
  Eigen::VectorXd solveFrom(const Solved& start, double lnw, double q) {
    const double w = std::exp(lnw), p = parameterOf(q);
    const Solved* before = nullptr;
    double bestDistance = std::numeric_limits<double>::infinity();
    for (const auto& s : solved_) {
      const double d = distance(start.lnw, start.q, s.lnw, s.q);
      if (&s != &start && d > 1e-9 && d < bestDistance) bestDistance = d, before = &s;
    }
    if (before) {
      const double a[2] = {(start.lnw - before->lnw) / 0.01, (start.q - before->q) / qSpan_};
      const double b[2] = {(lnw - start.lnw) / 0.01, (q - start.q) / qSpan_};
      const double t = (a[0] * b[0] + a[1] * b[1]) / (a[0] * a[0] + a[1] * a[1]);
      if (t > 1e-6 && t < 4) {
        try {
          return solve(start.x + t * (start.x - before->x), w, p);
        } catch (const SolverError&) {
        }
      }
    }
    return solve(start.x, w, p);
  }

  // The nearest solution made so far: where a solve at (ln w, q) starts.
  const Solved* nearest(double lnw, double q) const {
    const Solved* best = nullptr;
    double bestDistance = std::numeric_limits<double>::infinity();
    for (const auto& s : solved_) {
      const double d = distance(lnw, q, s.lnw, s.q);
      if (d < bestDistance) bestDistance = d, best = &s;
    }
    return best;
  }

  Condition at(double w, double q) {
    const double lnw = std::log(w), p = parameterOf(q);
    const Solved* start = nearest(lnw, q);
    if (!start) throw SolverError("peak continuation: no solution to start from");
    Condition c;
    c.x = solveFrom(*start, lnw, q);
    remember(lnw, q, c.x);
    rememberCentre(w, q, c.x);
    // dx/d ln w at the centre (J there, w dR/dw by a central difference): the sides'
    // predictor.
    Eigen::MatrixXd J;
    P_.jacobian(c.x, w, p, J);
    const DenseLu lu(J);
    const double e = 1e-6;
    Eigen::VectorXd Rp, Rm;
    P_.residual(c.x, w * (1 + e), p, Rp);
    P_.residual(c.x, w * (1 - e), p, Rm);
    Eigen::VectorXd z = -lu.solve((Rp - Rm) / (2 * e));
    if (!z.allFinite()) z.setZero(c.x.size());
    // ln m at ln w + {-3, -1, 1, 3} h / 2, each side solved from the centre along z.
    const double h = o_.frequencyStep;
    double L[4];
    Eigen::VectorXd side;
    for (int i = 0; i < 4; ++i) {
      const double u = 0.5 * h * double(2 * i - 3);
      // From the tangent's prediction; where that fails (z from an LU on the other side
      // of a stick-slip corner), from the centre itself.
      try {
        side = solve(c.x + u * z, w * std::exp(u), p);
      } catch (const SolverError&) {
        side = solve(c.x, w * std::exp(u), p);
      }
      const double m = P_.measure(side);
      if (!(m > 0)) throw SolverError("peak continuation: the response measure is zero (no response to follow)");
      L[i] = std::log(m);
    }
    c.measure = P_.measure(c.x);
    // G at ln w +- h / 2 by central differences over 2h, and at ln w their mean, its
    // derivative their difference over h. Not the second difference through the centre:
    // m itself has sparse kinks (a slope change of 6 in d ln m / d ln w measured on a
    // Jenkins oscillator at 256 samples) and one between the centre and a side made that
    // derivative wrong by up to 80 % while G, on the sides alone, stayed linear.
    const double Gplus = (L[3] - L[1]) / (2 * h), Gminus = (L[2] - L[0]) / (2 * h);
    c.G = 0.5 * (Gplus + Gminus);
    c.dGdlnw = (Gplus - Gminus) / h;
    return c;
  }

  void remember(double lnw, double q, const Eigen::VectorXd& x) {
    solved_.push_back({lnw, q, x});
    if (solved_.size() > 64) solved_.pop_front();
  }
  // The centre solutions by their exact (w, q): LOCA's points are where it evaluated G.
  void rememberCentre(double w, double q, const Eigen::VectorXd& x) { centres_[{w, q}] = x; }
  const Eigen::VectorXd* centre(double w, double q) const {
    const auto it = centres_.find({w, q});
    return it == centres_.end() ? nullptr : &it->second;
  }

  // The peak at q from frequency w: Newton on G in ln w.
  bool peakAt(double q, double w, Condition& c) {
    for (int it = 0; it < 30; ++it) {
      try {
        c = at(w, q);
      } catch (const SolverError&) {
        return false;
      }
      if (std::abs(c.G) <= o_.conditionTolerance * std::abs(c.dGdlnw)) {
        lastPeakW_ = w;
        return true;
      }
      if (!(c.dGdlnw < 0)) return false;  // not near a maximum
      const double step = std::clamp(-c.G / c.dGdlnw, -0.02, 0.02);
      w *= std::exp(step);
    }
    return false;
  }

  void setSpan(double qSpan) { qSpan_ = std::max(qSpan, 1e-12); }
  double lastPeakFrequency() const { return lastPeakW_; }

private:
  const PeakTrackingProblem& P_;
  const PeakContinuationOptions& o_;
  FollowedPeakCurve& out_;
  std::deque<Solved> solved_;
  std::map<std::pair<double, double>, Eigen::VectorXd> centres_;
  double qSpan_ = 1, lastPeakW_ = 0;
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
  if (!(o.frequencyStep > 0 && o.frequencyStep < 0.1))
    throw InputError("peak continuation", "frequencyStep must lie in (0, 0.1)");
  Timer timer;
  FollowedPeakCurve out;
  ReducedPeakCondition condition(P, o, out);
  const double q0 = condition.coordinateOf(o.from), q1 = condition.coordinateOf(o.to);
  condition.setSpan(std::abs(q1 - q0));
  condition.remember(std::log(w0), q0, x0);

  // The peak at the start, then LOCA on G(w; q) = 0 in y = w / w0.
  Condition first;
  if (!condition.peakAt(q0, w0, first)) {
    out.stopReason = "no peak found near " + std::to_string(w0) + " rad/s at the start of the range";
    out.seconds = timer.seconds();
    return out;
  }
  const double wStart = condition.lastPeakFrequency();
  ContinuationProblem reduced;
  reduced.size = 1;
  // G and dG/dy at the last (y, q) evaluated: LOCA asks for the Jacobian where it has
  // just had the residual.
  struct Last {
    double y = std::numeric_limits<double>::quiet_NaN(), q = 0, G = 0, dGdy = 0;
  };
  auto last = std::make_shared<Last>();
  const auto evaluate = [&condition, last, wStart](double y, double q) {
    if (!(y == last->y && q == last->q)) {
      if (!(y > 0)) throw SolverError("peak continuation: a frequency <= 0");
      const Condition c = condition.at(wStart * y, q);
      // F = G / |dG/d ln w|: the distance to the peak in ln w to first order, so that the
      // tolerance is a relative frequency however sharp or flat the peak.
      const double scale = std::max(std::abs(c.dGdlnw), 1e-300);
      *last = {y, q, c.G / scale, (c.dGdlnw / scale) / y};
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
  // LOCA's arclength rescaling kept the steps at a few 1e-3 in w / w0 (400 steps for
  // the Jenkins oscillator's range, unfinished); w / w0 and q are both of order one.
  loca.arcLengthScaling = false;
  const Branch branch = traceBranch(reduced, Eigen::VectorXd::Constant(1, 1.0), loca);
  out.searches = int(branch.points.size());
  out.complete = branch.finished;
  out.stopReason = branch.stopReason;
  for (const auto& pt : branch.points) {
    const double w = wStart * pt.x(0), q = pt.parameter - offset;
    const Eigen::VectorXd* x = condition.centre(w, q);
    if (!x) {  // not evaluated at exactly this point (never seen): the point is left out
      log::warn("peak continuation: no solution kept at a point of the continuation; left out");
      continue;
    }
    out.points.push_back({condition.parameterOf(q), w, P.measure(*x), *x, false});
  }
  if (out.points.empty()) out.points.push_back({o.from, wStart, first.measure, first.x, false});

  // The optimum: the smallest peak; inside the range, a golden section in q between its
  // neighbours, each value's peak found from the neighbours' interpolated frequency.
  for (std::size_t i = 0; i < out.points.size(); ++i)
    if (out.optimum < 0 || out.points[i].measure < out.points[std::size_t(out.optimum)].measure) out.optimum = int(i);
  const std::size_t k = std::size_t(out.optimum);
  if (o.locateOptimum && k > 0 && k + 1 < out.points.size()) {
    const auto peakMeasure = [&](double q, FollowedPeak& peak) {
      // The traced peak frequency, interpolated in q, as the start.
      double w = out.points[k].frequency;
      for (std::size_t i = 0; i + 1 < out.points.size(); ++i) {
        const double qa = condition.coordinateOf(out.points[i].parameter), qb = condition.coordinateOf(out.points[i + 1].parameter);
        if ((q - qa) * (q - qb) <= 0 && qa != qb) {
          w = out.points[i].frequency + (q - qa) / (qb - qa) * (out.points[i + 1].frequency - out.points[i].frequency);
          break;
        }
      }
      Condition c;
      if (!condition.peakAt(q, w, c)) return false;
      peak = {condition.parameterOf(q), condition.lastPeakFrequency(), c.measure, c.x, false};
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
