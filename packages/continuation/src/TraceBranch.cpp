#include "ContinuationEngines.hpp"

#include <sstream>

namespace cyclone::continuation {

std::string noConvergedStart(const NewtonResult& start, double tolerance) {
  std::ostringstream why;
  why << "no converged solution at the start of the range: Newton with line search from the guess stopped at ||R|| = "
      << start.residualNorm << " (tolerance " << tolerance
      << "; round-off of very different forces, e.g. a huge preload against a tiny excitation, needs a looser "
         "continuation tolerance)";
  return why.str();
}

ContinuationOptions locaOptions() {
  ContinuationOptions o;
  o.engine = ContinuationOptions::Engine::Loca;
  o.maxStep = 0.05;
  return o;
}

Branch traceBranch(const ContinuationProblem& problem, const Eigen::VectorXd& guess, const ContinuationOptions& o) {
  return o.engine == ContinuationOptions::Engine::Loca ? traceBranchWithLoca(problem, guess, o)
                                                       : traceBranchWithPredictorCorrector(problem, guess, o);
}

}  // namespace cyclone::continuation
