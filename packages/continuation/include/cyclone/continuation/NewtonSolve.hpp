#pragma once
// Newton's method with backtracking on ||F|| for F(x; p) = 0 at a fixed
// parameter: the start of a continuation, a solution at one frequency, or a
// solution carried to a refined harmonic set.
#include "cyclone/continuation/ArclengthContinuation.hpp"

namespace cyclone::continuation {

class DenseLu;

struct NewtonResult {
  bool converged = false;
  int iterations = 0;
  double residualNorm = 0;
  long krylovIterations = 0;  ///< GMRES iterations, where the steps were Krylov solves
};

/// Updates x in place. Throwing residuals count as failure (converged = false), and
/// so does a stagnation: no step along the Newton direction (down to 2^-30 of it)
/// decreases ||F|| (a spurious local minimum at the kinks of a nonsmooth system,
/// which more iterations do not leave).
/// lastFactors (optional): the LU of the last Jacobian factored (empty when x was
/// already a solution), for the caller's solves at the solution (e.g. a tangent); not
/// filled where the steps are Krylov solves (linearSolver, by useKrylov's rule).
NewtonResult solveNewton(const ContinuationProblem& problem, Eigen::VectorXd& x, double p, double tolerance = 1e-10,
                         int maxIterations = 200, DenseLu* lastFactors = nullptr,
                         ContinuationOptions::LinearSolver linearSolver = ContinuationOptions::LinearSolver::Auto);

}  // namespace cyclone::continuation
