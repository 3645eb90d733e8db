#pragma once
// The largest resonance peak of a frequency response followed over a parameter
// by a peak search at each parameter value (PeakSearch.hpp: Newton at fixed
// frequencies, golden section), for systems whose Jacobian jumps (friction
// through AFT: each stick-slip instant crossing a time sample). There the peak
// condition's derivatives jump too and an arclength corrector on it creeps
// (trackPeak; docs/decisions.md); a fixed-frequency Newton passes those
// corners. Each value starts from the peak before (a secant predictor in the
// parameter). Where the followed local maximum vanishes (it merges with a
// trough: a fold of the peak curve in the parameter) the band is swept and the
// largest peak there is taken, marked as a jump: the engineer's peak against
// the parameter is then discontinuous, as it is physically. The smallest peak
// (the optimum, e.g. the preload where friction damps most) is located by a
// golden section on the peaks between its grid neighbours.
#include <Eigen/Dense>
#include <functional>
#include <string>
#include <vector>

#include "cyclone/continuation/PeakSearch.hpp"
#include "cyclone/continuation/PeakTracking.hpp"

namespace cyclone::continuation {

/// A peak to follow: a solution near it and its frequency.
struct PeakStart {
  Eigen::VectorXd x;
  double frequency = 0, measure = 0;
  std::size_t index = 0;  ///< the point's index in the traced curve
};

/// A peak known at one parameter value (e.g. the top of a frequency curve traced there).
struct KnownPeak {
  double parameter = 0;
  PeakStart peak;
};

struct PeakFollowingOptions {
  /// The parameter values, monotone; the first is the start's (logarithmicValues()
  /// spaces them evenly in log p).
  std::vector<double> parameters;
  double bandFrom = 0, bandTo = 0;  ///< the frequency band a sweep covers (at
                                    ///< the start and at a jump)
  PeakSearchOptions search;         ///< in the frequency; window and steps relative to
                                    ///< it are set per value
  ContinuationOptions sweep;        ///< the band sweeps' options (from, to are the band)
  bool locateOptimum = true;        ///< the smallest peak by golden section between its grid neighbours
  /// At these parameter values a search from each known peak too, the larger of it and
  /// the followed one taken (marked as a jump where the known one is larger): a peak that
  /// rises between two values of the grid, and overtakes the followed one without it
  /// vanishing, is seen where a curve was traced; the following goes on from it.
  std::vector<KnownPeak> knownPeaks;
};

struct FollowedPeak {
  double parameter = 0, frequency = 0, measure = 0;
  Eigen::VectorXd x;
  bool jump = false;  ///< the followed maximum vanished before this value; this
                      ///< one is the band's largest
};

/// How a peak's following ended: what a calling program branches on.
/// FollowedPeakCurve::stopReason says the same as a sentence, with where.
enum class PeakFollowingEnd {
  Running,              ///< not ended
  RangeEnd,             ///< every parameter value has its peak (complete)
  NoPeakAtStart,        ///< no peak (or no response) at the range's first value
  PeakVanished,         ///< the followed peak vanished and the band's sweep found none
  ValueNotReached,      ///< none of the several followed peaks reached a value (followPeaks)
  ContinuationStopped,  ///< continuePeak's continuation ended inside the range (FollowedPeakCurve::branchEnd: how)
};
/// The outcome's name in files ("range_end", "peak_vanished", ...).
const char* peakFollowingEndName(PeakFollowingEnd end);

struct FollowedPeakCurve {
  std::vector<FollowedPeak> points;  ///< in parameter order (the optimum among them when located)
  bool complete = false;             ///< every parameter value has a peak
  PeakFollowingEnd end = PeakFollowingEnd::Running;
  BranchEnd branchEnd = BranchEnd::Running;  ///< continuePeak: how its continuation's branch ended
  std::string stopReason;
  int sweeps = 0, searches = 0, solves = 0;
  double seconds = 0;
  /// The optimum: the smallest peak; located (to the search's tolerance in the
  /// parameter) when locateOptimum and it lies inside the range.
  int optimum = -1;  ///< index into points
  bool optimumLocated = false;
  /// The points marked as a jump to another peak.
  int jumps() const;
  /// The index of the largest peak (the first of equal ones; 0 without points).
  std::size_t largestPeak() const;
};


/// The interior local maxima of a traced frequency curve that stand out: each one's
/// prominence (how far the measure falls, along the path, before it rises above the
/// peak again or the sweep ends, the lesser of both sides) at least `prominence` of
/// its value (a curve's kinks make tiny maxima that are not peaks). Each sweep of the
/// curve (Branch::segmentStarts) is a path of its own: the last point of one and the
/// first of the next are not neighbours. Largest first.
std::vector<PeakStart> prominentPeaks(const Branch& curve, const std::function<double(const Eigen::VectorXd&)>& measure,
                                      double prominence = 0.05);

/// Every start followed over options.parameters (each as followPeak does), and per value
/// the largest of them: where another followed peak overtakes, the point is marked as a
/// jump. With one start, followPeak's curve (its optimum located); with several the
/// optimum is the grid's smallest.
FollowedPeakCurve followPeaks(const PeakTrackingProblem& problem, const std::vector<PeakStart>& starts,
                              const PeakFollowingOptions& options);

/// n values from `from` to `to` (both ends included), evenly spaced in log p.
std::vector<double> logarithmicValues(double from, double to, int n);

/// From a peak (x0 at frequency w0, parameter options.parameters[0]) or, with x0 empty,
/// from a sweep of the band there.
FollowedPeakCurve followPeak(const PeakTrackingProblem& problem, const Eigen::VectorXd& x0, double w0,
                             const PeakFollowingOptions& options);

}  // namespace cyclone::continuation
