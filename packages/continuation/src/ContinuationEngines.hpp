#pragma once
// The two engines behind traceBranch (ArclengthContinuation.hpp).
#include <string>

#include "cyclone/continuation/ArclengthContinuation.hpp"
#include "cyclone/continuation/NewtonSolve.hpp"

namespace cyclone::continuation {

Branch traceBranchWithPredictorCorrector(const ContinuationProblem& problem, const Eigen::VectorXd& guess,
                                         const ContinuationOptions& options);
Branch traceBranchWithLoca(const ContinuationProblem& problem, const Eigen::VectorXd& guess,
                           const ContinuationOptions& options);

/// The stop reason of a branch whose start did not converge.
std::string noConvergedStart(const NewtonResult& start, double tolerance);

}  // namespace cyclone::continuation
