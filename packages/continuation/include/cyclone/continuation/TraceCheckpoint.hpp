#pragma once
// A trace's state saved as it goes, so a killed run continues where it stopped
// (`cyclone run --resume`, docs/scenes.md) instead of starting again.
//
// traceBranch (ArclengthContinuation.hpp) keys each trace by a digest of what
// determines its path: the problem's size, the options, the start guess and the
// residual there (two problems that differ anywhere the start sees differ in it). A
// trace that finished is read back whole; an unfinished one of the predictor-
// corrector continues from its saved state between two steps (every point, tangent
// and measure, the metric, the step and the counters), so the resumed curve is the
// one an uninterrupted run traces, point for point. LOCA's stepper keeps its state
// inside LOCA: its unfinished traces start again (finished ones are read back).
#include <Eigen/Dense>
#include <optional>
#include <string>
#include <vector>

#include "cyclone/continuation/ArclengthContinuation.hpp"

namespace cyclone::continuation {

struct TraceState {
  Branch branch;          ///< the points so far, or the whole result when complete
  bool complete = false;  ///< the trace ended; nothing below is used
  // The predictor-corrector between two steps (its last point is branch.points.back()).
  std::vector<Eigen::VectorXd> tangentX;  ///< per point (size 0 where not known)
  std::vector<double> tangentP, measures;
  Eigen::VectorXd directionX;  ///< the unit tangent the next step follows
  double directionP = 0, step = 0;
  double scaleP = 1;
  std::vector<double> scaleX, largestNorm, scaleFloor;  ///< per scale group (ContinuationProblem::scaleGroups)
  long retractions = 0, anchor = 0, creepChecked = 0;
  /// Secant steps on (a stair of kinks), the last steps' verdicts that switch them on
  /// (1: held small by the tangent's turn), and the smooth steps in a row that end them.
  long secant = 0, smoothRun = 0;
  std::vector<int> heldSteps;
};

/// Where traces keep their states (io::TraceCheckpointDirectory: HDF5 files).
class TraceCheckpoints {
public:
  virtual ~TraceCheckpoints() = default;
  /// The state saved under `key`; none when there is none or it cannot be read (a
  /// damaged checkpoint costs its recomputation, not the run).
  virtual std::optional<TraceState> load(const std::string& key) = 0;
  /// Replaces the state under `key` atomically (a kill during the save leaves the one before).
  virtual void save(const std::string& key, const TraceState& state) = 0;
  /// Seconds of work between two saves of an unfinished trace.
  double intervalSeconds = 5;
};

/// The key traceBranch files a trace under (32 hex digits): a digest of the problem's size,
/// the options, the guess, and the residual at the guess and at four fixed probes around it
/// (what acts only in motion, such as a gap's clearance or a friction coefficient, does not
/// show in the residual at rest).
std::string traceKey(const ContinuationProblem& problem, const Eigen::VectorXd& guess,
                     const ContinuationOptions& options);

}  // namespace cyclone::continuation
