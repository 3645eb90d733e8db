#include "cyclone/continuation/PeakSearch.hpp"

#include <cmath>
#include <limits>
#include <optional>
#include <sstream>

#include "cyclone/continuation/NewtonSolve.hpp"
#include "cyclone/core/Error.hpp"

namespace cyclone::continuation {

namespace {

struct Solved {
  double p = 0;
  Eigen::VectorXd x;
  double g = 0;
};

// Linear in p through a and b (b's solution when they coincide).
Eigen::VectorXd predict(const Solved& a, const Solved& b, double p) {
  if (a.p == b.p) return b.x;
  return b.x + (b.x - a.x) * ((p - b.p) / (b.p - a.p));
}

}  // namespace

PeakSearchResult findLocalPeak(const ContinuationProblem& problem, const Eigen::VectorXd& x0, double p0,
                               const std::function<double(const Eigen::VectorXd&)>& measure,
                               const PeakSearchOptions& o) {
  if (!(o.step > 0 && o.minStep > 0 && o.maxStep >= o.step && o.window > 0 && o.parameterTolerance > 0))
    throw InputError("peak search", "needs 0 < minStep, 0 < step <= maxStep, window > 0, parameterTolerance > 0");
  PeakSearchResult out;
  Solved best;
  best.g = -std::numeric_limits<double>::infinity();  // any measure, negative ones too
  auto solveAt = [&](double p, Eigen::VectorXd guess) -> std::optional<Solved> {
    ++out.solves;
    if (!solveNewton(problem, guess, p, o.tolerance, o.maxNewtonIterations).converged) return std::nullopt;
    Solved s{p, std::move(guess), 0};
    s.g = measure(s.x);
    if (!std::isfinite(s.g)) return std::nullopt;
    return s;
  };
  auto accept = [&](const Solved& s) {  // only points on the path count for the best
    if (s.g > best.g) best = s;
    out.path.emplace_back(s.p, s.x);
  };
  auto finish = [&](bool found, const std::string& reason) {
    out.found = found, out.reason = reason;
    out.parameter = best.p, out.value = best.g, out.x = best.x;
    return out;
  };

  const auto start = solveAt(p0, x0);
  if (!start) return finish(false, "no solution at the start, p = " + std::to_string(p0));
  accept(*start);

  // One step from cur in direction dir, the step cut until Newton converges to a point
  // near the secant's prediction (a solution far from it lies on another branch).
  double h = o.step;
  auto stepFrom = [&](const Solved& prev, const Solved& cur, int dir, std::string& why) -> std::optional<Solved> {
    const double edge = p0 + dir * o.window;
    for (;;) {
      double p = cur.p + dir * h;
      if (dir * (p - edge) > 0) p = edge;
      if (p == cur.p) {
        why = "the measure still rises at the window's edge, p = " + std::to_string(edge);
        return std::nullopt;
      }
      const Eigen::VectorXd guess = predict(prev, cur, p);
      auto s = solveAt(p, guess);
      const double lastChange = (cur.x - prev.x).norm();
      if (s && (prev.p == cur.p || (s->x - guess).norm() <= 5 * lastChange)) {
        accept(*s);
        return s;
      }
      h *= 0.5;
      if (h < o.minStep) {
        std::ostringstream msg;
        msg << "no solution near the path beyond p = " << cur.p << " (steps cut below " << o.minStep
            << "): a fold; the peak value is at least the best point's";
        why = msg.str();
        return std::nullopt;
      }
    }
  };

  // Uphill: the first direction whose first step raises the measure.
  Solved left, mid = *start, right;
  std::string why, whyDown;
  const auto up = stepFrom(mid, mid, +1, why);
  int dir = 0;
  Solved prev = mid, cur = mid;
  if (up && up->g > mid.g) {
    dir = +1, cur = *up;
  } else {
    h = o.step;
    const auto down = stepFrom(mid, mid, -1, whyDown);
    if (down && down->g > mid.g) {
      dir = -1, cur = *down;
    } else if (up && down) {
      left = *down, right = *up;  // the start is the highest of three: bracketed
    } else {
      return finish(false, up ? whyDown : why);
    }
  }
  if (dir != 0) {
    for (;;) {
      const auto next = stepFrom(prev, cur, dir, why);
      if (!next) return finish(false, why);
      if (next->g > cur.g) {
        prev = cur, cur = *next;
        h = std::min(1.5 * h, o.maxStep);
        continue;
      }
      mid = cur;
      left = dir > 0 ? prev : *next;
      right = dir > 0 ? *next : prev;
      break;
    }
  }

  // Golden-section search on [left, right] with mid the highest point inside.
  const double golden = 0.5 * (3 - std::sqrt(5.0));
  while (right.p - left.p > o.parameterTolerance) {
    const bool rightPart = right.p - mid.p > mid.p - left.p;
    const Solved& end = rightPart ? right : left;
    const double p = mid.p + golden * (end.p - mid.p);
    auto s = solveAt(p, predict(end, mid, p));
    if (!s) s = solveAt(p, end.x);
    if (!s) {
      std::ostringstream msg;
      msg << "no solution at p = " << p << " inside the bracket [" << left.p << ", " << right.p << "]";
      return finish(false, msg.str());
    }
    accept(*s);
    if (s->g > mid.g) {
      (rightPart ? left : right) = mid;
      mid = *s;
    } else {
      (rightPart ? right : left) = *s;
    }
  }
  return finish(true, "");
}

}  // namespace cyclone::continuation
