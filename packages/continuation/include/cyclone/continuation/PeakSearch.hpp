#pragma once
// The largest value of a response measure g(x) along the solutions of
// F(x; p) = 0 near a known one: steps at a fixed parameter (Newton at each p
// from its neighbours' secant predictor) uphill in g, then golden-section
// search on the bracket. No arclength: a fixed-parameter Newton passes the
// corners of a nonsmooth path (friction, AFT) that stall an arclength corrector,
// and the search needs a handful of solves, not a curve. It cannot pass a fold:
// a search that meets one stops there and says so, the value it reached a
// lower bound of the peak, not the peak (findPeakPastFold then traces past it).
#include <Eigen/Dense>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "cyclone/continuation/ArclengthContinuation.hpp"

namespace cyclone::continuation {

struct PeakSearchOptions {
  double step = 1e-3;                ///< first step in p (absolute)
  double maxStep = 1e-2;             ///< the walk's steps grow by 1.5 up to this
  double minStep = 1e-7;             ///< a step cut below this (no solution beyond): a fold, the search stops
  double window = 0.1;               ///< the search stays within |p - p0| <= window
  double parameterTolerance = 1e-5;  ///< the bracket's width at which the peak is taken
  double tolerance = 1e-10;          ///< Newton: ||F||_2
  int maxNewtonIterations = 50;
};

struct PeakSearchResult {
  bool found = false;  ///< a local maximum bracketed and narrowed to parameterTolerance
  double parameter = 0, value = 0;  ///< the best point solved (a lower bound when not found)
  Eigen::VectorXd x;                ///< its solution
  std::string reason;               ///< why not found (a fold, the window's edge, no solution at p0)
  int solves = 0;                   ///< Newton solves
  /// Every solution the search accepted (p, x), in the order solved: points on the path
  /// near the peak (e.g. starts for the same search on a refined system).
  std::vector<std::pair<double, Eigen::VectorXd>> path;
};

/// x0: a solution or a close guess at p0 (solved first). measure: g(x), e.g. the peak
/// magnitude of one DOF's response.
PeakSearchResult findLocalPeak(const ContinuationProblem& problem, const Eigen::VectorXd& x0, double p0,
                               const std::function<double(const Eigen::VectorXd&)>& measure,
                               const PeakSearchOptions& options);

/// A search that stopped at a fold (not found, its path known) carried past it: the path
/// traced by arclength (traceBranch, the measure's local maxima located on it) from the
/// search's first point, the way it walked and within its window, so that it rounds the
/// fold and comes back over the top (an overhanging peak, or a branch folded below its
/// top); the largest value of the measure on that trace is the peak where it lies inside
/// the trace, not at its first or last point. At most `maxPoints` points. Returns the
/// search's result (its reason extended) where no top is found.
PeakSearchResult findPeakPastFold(const ContinuationProblem& problem, const PeakSearchResult& search,
                                  const std::function<double(const Eigen::VectorXd&)>& measure,
                                  const PeakSearchOptions& options, int maxPoints);

}  // namespace cyclone::continuation
