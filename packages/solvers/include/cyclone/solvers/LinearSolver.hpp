#pragma once
// Solves K x = b for a symmetric positive definite K: the sparse direct path
// (CHOLMOD, default) or the iterative path for meshes too big to factor
// (Belos CG with a MueLu smoothed-aggregation preconditioner; its coarse level
// uses relaxation, not Debian's KLU2, which is wrong on several MPI ranks).
#include <string>

#include "cyclone/fe/LinearAlgebra.hpp"

namespace cyclone::solvers {

enum class LinearSolverKind { Direct, Iterative };

/// "direct" or "iterative"; InputError naming `where` otherwise.
LinearSolverKind linearSolverKindFromName(const std::string& name, const std::string& where);

struct LinearSolveOptions {
  LinearSolverKind kind = LinearSolverKind::Direct;
  double tolerance = 1e-10;  ///< iterative: relative residual
  int maxIterations = 2000;
  /// Iterative: the 6 rigid-body modes (Assembler::rigidBodyModes) for MueLu's
  /// smoothed aggregation on elasticity; null falls back to scalar aggregation.
  Teuchos::RCP<const linalg::MultiVector> nearNullSpace;
  int blockSize = 3;  ///< equations per node for aggregation (1 if components are constrained unevenly)
};

struct LinearSolveReport {
  int iterations = 0;              ///< 0 for direct
  double relativeResidual = 0;     ///< ||b - K x|| / ||b||, measured after the solve
  double setupSeconds = 0, solveSeconds = 0;
};

/// x may hold an initial guess (iterative). Throws SolverError if the residual
/// check fails.
LinearSolveReport solveLinear(const linalg::Matrix& K, const linalg::MultiVector& b, linalg::MultiVector& x,
                              const LinearSolveOptions& options);

/// The iterative path alone (IterativeSolver.cpp holds the Belos/MueLu templates).
LinearSolveReport solveIterative(const linalg::Matrix& K, const linalg::MultiVector& b, linalg::MultiVector& x,
                                 const LinearSolveOptions& options);

}  // namespace cyclone::solvers
