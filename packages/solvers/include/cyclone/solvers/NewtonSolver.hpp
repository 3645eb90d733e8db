#pragma once
// Newton's method for a distributed nonlinear system R(u) = 0 through NOX
// (line-search based Newton, backtracking line search), with the Jacobian
// solves done by the CHOLMOD direct solver. The caller provides the residual
// and the (symmetric positive definite) Jacobian.
#include <functional>
#include <memory>

#include "cyclone/fe/LinearAlgebra.hpp"

namespace cyclone::solvers {

class DirectSolver;

struct NewtonProblem {
  /// R = R(u); returns nothing (NOX takes the norm itself).
  std::function<void(const linalg::MultiVector& u, linalg::MultiVector& R)> residual;
  /// The Jacobian dR/du at u.
  std::function<Teuchos::RCP<linalg::Matrix>(const linalg::MultiVector& u)> jacobian;
  /// Optional: an approximation of the Jacobian that is already factored (e.g. the
  /// linear stiffness a predictor factored). NOX's limited-memory Broyden method then
  /// starts from it and corrects it by rank-one updates; `jacobian` is never called.
  /// The solve ends unconverged as soon as the residual falls by less than half in an
  /// iteration: the caller then solves with Newton (approximateFactor unset).
  Teuchos::RCP<const linalg::Matrix> approximateJacobian;
  std::shared_ptr<const DirectSolver> approximateFactor;
};

struct NewtonOptions {
  double absoluteTolerance = 1e-10;  ///< on ||R||_2
  int maxIterations = 20;
};

struct NewtonReport {
  bool converged = false;
  int iterations = 0;
  int jacobians = 0;  ///< true Jacobians assembled and factored
  double residualNorm = 0;
};

/// u holds the initial guess on entry and the last iterate on return. A Jacobian
/// that cannot be factored ends the solve as not converged (the caller cuts its step).
NewtonReport solveNewton(const NewtonProblem& problem, linalg::MultiVector& u, const NewtonOptions& options);

}  // namespace cyclone::solvers
