#pragma once
// Private to continuation: the golden-section search every extremum over a parameter
// uses (a peak over the frequency, PeakSearch; the smallest peak over a study's
// parameter, PeakFollowing and PeakContinuation).
#include <cmath>
#include <optional>

namespace cyclone::continuation::detail {

/// From a bracket left < mid < right (in `coordinate`) whose mid is better than both
/// ends, each step evaluates one point a golden fraction of the way from mid into the
/// larger part and keeps the better three: one evaluation a step, the bracket shrinking
/// by the golden ratio every two. `evaluate(p, end, mid)` gives the trial at p (between
/// mid and the bracket's `end`, the trials it may start from) or nothing where it cannot
/// (the search stops: nothing returned); `better(a, b)` says whether a beats b. Returns
/// the best trial once the bracket is narrower than `tolerance`.
template <class Trial, class Coordinate, class Evaluate, class Better>
std::optional<Trial> goldenSection(Trial left, Trial mid, Trial right, double tolerance, Coordinate&& coordinate,
                                   Evaluate&& evaluate, Better&& better) {
  const double golden = 0.5 * (3 - std::sqrt(5.0));
  while (std::abs(coordinate(right) - coordinate(left)) > tolerance) {
    const bool rightPart = std::abs(coordinate(right) - coordinate(mid)) > std::abs(coordinate(mid) - coordinate(left));
    const Trial& end = rightPart ? right : left;
    const double p = coordinate(mid) + golden * (coordinate(end) - coordinate(mid));
    std::optional<Trial> s = evaluate(p, end, mid);
    if (!s) return std::nullopt;
    if (better(*s, mid)) {
      (rightPart ? left : right) = std::move(mid);
      mid = std::move(*s);
    } else {
      (rightPart ? right : left) = std::move(*s);
    }
  }
  return mid;
}

}  // namespace cyclone::continuation::detail
