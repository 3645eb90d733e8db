#include "cyclone/continuation/PeakSearch.hpp"

#include "GoldenSection.hpp"

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

// One search's state: the problem, the best point so far and the path walked.
class PeakSearch {
public:
  PeakSearch(const ContinuationProblem& problem, double p0, const std::function<double(const Eigen::VectorXd&)>& measure,
             const PeakSearchOptions& o)
      : problem_(problem), p0_(p0), measure_(measure), o_(o), h_(o.step) {
    best_.g = -std::numeric_limits<double>::infinity();  // any measure, negative ones too
  }
  PeakSearchResult run(const Eigen::VectorXd& x0);

private:
  std::optional<Solved> solveAt(double p, Eigen::VectorXd guess) {
    ++out_.solves;
    if (!solveNewton(problem_, guess, p, o_.tolerance, o_.maxNewtonIterations).converged) return std::nullopt;
    Solved s{p, std::move(guess), 0};
    s.g = measure_(s.x);
    if (!std::isfinite(s.g)) return std::nullopt;
    return s;
  }
  void accept(const Solved& s) {  // only points on the path count for the best
    if (s.g > best_.g) best_ = s;
    out_.path.emplace_back(s.p, s.x);
  }
  PeakSearchResult finish(bool found, const std::string& reason) {
    out_.found = found, out_.reason = reason;
    out_.parameter = best_.p, out_.value = best_.g, out_.x = best_.x;
    return out_;
  }
  std::optional<Solved> stepFrom(const Solved& prev, const Solved& cur, int dir, std::string& why);
  bool bracket(Solved& left, Solved& mid, Solved& right, std::string& why);
  bool goldenSection(Solved left, Solved mid, Solved right, std::string& why);

  const ContinuationProblem& problem_;
  const double p0_;
  const std::function<double(const Eigen::VectorXd&)>& measure_;
  const PeakSearchOptions& o_;
  double h_;  // the current step
  PeakSearchResult out_;
  Solved best_;
};

// One step from cur in direction dir, the step cut until Newton converges to a point
// near the secant's prediction (a solution far from it lies on another branch).
std::optional<Solved> PeakSearch::stepFrom(const Solved& prev, const Solved& cur, int dir, std::string& why) {
  const double edge = p0_ + dir * o_.window;
  for (;;) {
    double p = cur.p + dir * h_;
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
    h_ *= 0.5;
    if (h_ < o_.minStep) {
      std::ostringstream msg;
      msg << "no solution near the path beyond p = " << cur.p << " (steps cut below " << o_.minStep
          << "): a fold; the peak value is at least the best point's";
      why = msg.str();
      return std::nullopt;
    }
  }
}

// Uphill from mid (the start) in the first direction whose first step raises the
// measure, until it falls: left < mid < right with mid the highest of the three.
bool PeakSearch::bracket(Solved& left, Solved& mid, Solved& right, std::string& why) {
  std::string whyDown;
  const auto up = stepFrom(mid, mid, +1, why);
  int dir = 0;
  Solved prev = mid, cur = mid;
  if (up && up->g > mid.g) {
    dir = +1, cur = *up;
  } else {
    h_ = o_.step;
    const auto down = stepFrom(mid, mid, -1, whyDown);
    if (down && down->g > mid.g) {
      dir = -1, cur = *down;
    } else if (up && down) {
      left = *down, right = *up;  // the start is the highest of three: bracketed
      return true;
    } else {
      if (up) why = whyDown;
      return false;
    }
  }
  for (;;) {
    const auto next = stepFrom(prev, cur, dir, why);
    if (!next) return false;
    if (next->g > cur.g) {
      prev = cur, cur = *next;
      h_ = std::min(1.5 * h_, o_.maxStep);
      continue;
    }
    mid = cur;
    left = dir > 0 ? prev : *next;
    right = dir > 0 ? *next : prev;
    return true;
  }
}

// Golden-section search on [left, right] with mid the highest point inside.
bool PeakSearch::goldenSection(Solved left, Solved mid, Solved right, std::string& why) {
  const auto solved = detail::goldenSection(
      left, mid, right, o_.parameterTolerance, [](const Solved& s) { return s.p; },
      [&](double p, const Solved& end, const Solved& inner) {
        auto s = solveAt(p, predict(end, inner, p));
        if (!s) s = solveAt(p, end.x);
        if (s) {
          accept(*s);
        } else {
          std::ostringstream msg;
          msg << "no solution at p = " << p << " inside the bracket [" << std::min(end.p, inner.p) << ", "
              << std::max(end.p, inner.p) << "]";
          why = msg.str();
        }
        return s;
      },
      [](const Solved& a, const Solved& b) { return a.g > b.g; });
  return solved.has_value();
}

PeakSearchResult PeakSearch::run(const Eigen::VectorXd& x0) {
  const auto start = solveAt(p0_, x0);
  if (!start) return finish(false, "no solution at the start, p = " + std::to_string(p0_));
  accept(*start);
  Solved left, mid = *start, right;
  std::string why;
  if (!bracket(left, mid, right, why) || !goldenSection(left, mid, right, why)) return finish(false, why);
  return finish(true, "");
}

}  // namespace

PeakSearchResult findLocalPeak(const ContinuationProblem& problem, const Eigen::VectorXd& x0, double p0,
                               const std::function<double(const Eigen::VectorXd&)>& measure,
                               const PeakSearchOptions& o) {
  if (!(o.step > 0 && o.minStep > 0 && o.maxStep >= o.step && o.window > 0 && o.parameterTolerance > 0))
    throw InputError("peak search", "needs 0 < minStep, 0 < step <= maxStep, window > 0, parameterTolerance > 0");
  return PeakSearch(problem, p0, measure, o).run(x0);
}

PeakSearchResult findPeakPastFold(const ContinuationProblem& problem, const PeakSearchResult& search,
                                  const std::function<double(const Eigen::VectorXd&)>& measure,
                                  const PeakSearchOptions& o, int maxPoints) {
  if (search.found || search.path.empty()) return search;
  const auto& [p0, x0] = search.path.front();
  if (search.parameter == p0) return search;  // no walk: no direction to trace
  ContinuationProblem traced = problem;
  traced.measure = measure;
  ContinuationOptions options;
  options.from = p0;
  options.to = p0 + (search.parameter < p0 ? -o.window : o.window);
  options.tolerance = o.tolerance;
  options.maxSteps = maxPoints;
  Branch branch;
  try {
    branch = traceBranch(traced, x0, options);
  } catch (const Error&) {
    return search;
  }
  PeakSearchResult out = search;
  out.solves += branch.statistics.newtonIterations;
  std::size_t best = 0;
  double value = -std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < branch.points.size(); ++i) {
    const double g = measure(branch.points[i].x);
    if (g > value) value = g, best = i;
    out.path.emplace_back(branch.points[i].parameter, branch.points[i].x);
  }
  if (branch.points.size() < 3 || best == 0 || best + 1 == branch.points.size()) {
    out.reason += "; traced on by arclength (" + std::to_string(branch.points.size()) + " points), no top inside";
    return out;
  }
  out.found = true;
  out.parameter = branch.points[best].parameter, out.value = value, out.x = branch.points[best].x;
  out.reason.clear();
  return out;
}

}  // namespace cyclone::continuation
