#pragma once
// The two engines behind traceBranch (ArclengthContinuation.hpp).
#include <functional>
#include <string>

#include "cyclone/continuation/ArclengthContinuation.hpp"
#include "cyclone/continuation/NewtonSolve.hpp"

namespace cyclone::continuation {

struct TraceState;

/// The predictor-corrector's saving: where from (a saved unfinished state, or none)
/// and how to save (TraceCheckpoint.hpp).
struct TraceCheckpointing {
  const TraceState* resumeFrom = nullptr;
  std::function<void(const TraceState&)> save;
  double intervalSeconds = 5;  ///< of work between two saves
};

Branch traceBranchWithPredictorCorrector(const ContinuationProblem& problem, const Eigen::VectorXd& guess,
                                         const ContinuationOptions& options,
                                         const TraceCheckpointing* checkpointing = nullptr);
Branch traceBranchWithLoca(const ContinuationProblem& problem, const Eigen::VectorXd& guess,
                           const ContinuationOptions& options);

/// The stop reason of a branch whose start did not converge.
std::string noConvergedStart(const NewtonResult& start, double tolerance);

}  // namespace cyclone::continuation
