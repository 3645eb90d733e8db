#pragma once
// Private to continuation: golden-section search for the smallest measure on [a, b],
// the optimum of a peak over a parameter (PeakFollowing's and PeakContinuation's).
#include <cmath>
#include <optional>

namespace cyclone::continuation::detail {

/// `evaluate(p, trial)` fills a trial at p and returns false where it cannot (the search
/// stops: nothing returned); `measure(trial)` is what is minimised. The two inner points
/// are kept, so each step costs one evaluation. Returns the better inner trial once the
/// bracket is narrower than `tolerance`.
template <class Trial, class Evaluate, class Measure>
std::optional<Trial> goldenSectionMinimum(double a, double b, double tolerance, Evaluate&& evaluate,
                                          Measure&& measure) {
  const double golden = 0.5 * (std::sqrt(5.0) - 1);
  double c = b - golden * (b - a), d = a + golden * (b - a);
  Trial pc, pd;
  if (!evaluate(c, pc) || !evaluate(d, pd)) return std::nullopt;
  while (std::abs(b - a) > tolerance) {
    if (measure(pc) < measure(pd)) {
      b = d, d = c, pd = pc, c = b - golden * (b - a);
      if (!evaluate(c, pc)) return std::nullopt;
    } else {
      a = c, c = d, pc = pd, d = a + golden * (b - a);
      if (!evaluate(d, pd)) return std::nullopt;
    }
  }
  return measure(pc) < measure(pd) ? pc : pd;
}

}  // namespace cyclone::continuation::detail
