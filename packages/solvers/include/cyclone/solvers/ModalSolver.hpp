#pragma once
// Generalised symmetric eigenproblem K x = lambda M x, lowest modes, by
// Anasazi's block Krylov-Schur on the shift-inverted operator (K - sigma M)^{-1} M
// with the CHOLMOD factorization. Block size >= 2 so that double modes (cyclic
// pairs, symmetric structures) are caught together.
#include <functional>
#include <limits>
#include <vector>

#include <Eigen/Core>

#include "cyclone/fe/LinearAlgebra.hpp"
#include "cyclone/solvers/DirectSolver.hpp"

namespace cyclone::solvers {

/// Shift-invert block Krylov-Schur (factorization, the default) or LOBPCG with a
/// MueLu preconditioner (no factorization: for meshes too big to factor; K must be
/// positive definite, i.e. a constrained model, and the shift is not used).
enum class EigenMethod { ShiftInvert, Lobpcg };

struct ModalOptions {
  EigenMethod method = EigenMethod::ShiftInvert;
  /// LOBPCG: near null space for the MueLu preconditioner (Assembler::rigidBodyModes).
  /// Required unless equationsPerNode is 1: without it LOBPCG stalls.
  Teuchos::RCP<const linalg::MultiVector> nearNullSpace;
  /// LOBPCG: MueLu's block size, the unknowns per node: 3 x copies when the transform
  /// is blockedByNode() (a cyclic pair has 6), otherwise 1.
  int equationsPerNode = 3;
  int numModes = 10;
  /// Shift sigma in (rad/s)^2; must lie below the lowest eigenvalue so that
  /// K - sigma M is positive definite. 0 suits constrained models. A free body
  /// needs a negative shift of the order of its first elastic eigenvalue: a tiny
  /// one leaves K - sigma M so ill-conditioned that elastic modes cannot converge.
  /// automaticShift() (NaN): 0 if K factors, otherwise a rough first pass finds the
  /// first elastic eigenvalue and the real pass shifts to minus that.
  double shift = 0.0;
  static double automaticShift() { return std::numeric_limits<double>::quiet_NaN(); }
  /// TravellingWavePairs: K and M are a cyclic real form in travelling-wave pairs
  /// (cyclic::travellingWavePaired): K - sigma M is factored as its Hermitian half
  /// (DirectSolver::Structure), a quarter of the real form's factor.
  DirectSolver::Structure structure = DirectSolver::Structure::General;
  int blockSize = 4;  ///< at least the largest multiplicity sought (6 for a free body)
  int numBlocks = 0;  ///< Krylov blocks; 0 picks enough for numModes
  double tolerance = 1e-10;
  int maxRestarts = 200;
};

struct ModalResult {
  std::vector<double> eigenvalues;   ///< omega^2, ascending
  std::vector<double> frequenciesHz;
  std::vector<double> residuals;     ///< ||K x - lambda M x|| / ((||K||_F + |lambda| ||M||_F) ||x||)
  Teuchos::RCP<linalg::MultiVector> modes;  ///< mass-normalised: x^T M x = 1
  int operatorApplies = 0;  ///< vectors through the operator (shift-invert: right-hand sides solved)
  double shift = 0;  ///< the shift used (chosen when automatic; 0 for LOBPCG)
  double factorSeconds = 0, solveSeconds = 0;
};

/// Throws SolverError when fewer than numModes converge (with how many did).
ModalResult solveModes(const linalg::Matrix& K, const linalg::Matrix& M, const ModalOptions& options);

/// K and M given by their action on blocks of real vectors (size rows, one column per
/// vector), with the shifted matrix already factored by the caller: for operators held
/// outside Tpetra, e.g. a cyclic sector's complex Hermitian form acting on its real form.
/// One process; the start block is seeded, so the answer does not depend on what ran before.
struct ShiftInvertedProblem {
  long long size = 0;
  double shift = 0;                 ///< sigma: solveShifted applies (K - sigma M)^{-1}
  double normK = 0, normM = 0;      ///< Frobenius norms, for the modes' backward errors
  std::function<void(const Eigen::MatrixXd& x, Eigen::MatrixXd& y)> applyK, applyM, solveShifted;
  /// Optional, both or neither: the halves of solveShifted for the factor
  /// P (K - sigma M) P^T = L L^T, y = L^{-1} P x and y = P^T L^{-T} x. Then the
  /// eigen-solver iterates on the standard form L^{-1} P M P^T L^{-T}: no M in its
  /// inner products, which would otherwise cost several M products per solve.
  std::function<void(const Eigen::MatrixXd& x, Eigen::MatrixXd& y)> solveLower, solveUpper;
  /// Optional: a map that commutes with K and M and takes each eigenvector to another of
  /// the same eigenvalue (i on a travelling-wave real form), so that every degenerate
  /// pair is returned whole.
  std::function<void(const Eigen::MatrixXd& x, Eigen::MatrixXd& y)> partner;
};
/// Block Krylov-Schur on (K - sigma M)^{-1} M as solveModes above (options.shift and
/// options.method are not used). Throws SolverError when fewer than numModes converge.
/// Both solveModes: Anasazi's converged vectors are taken as a subspace and the modes
/// come from a Rayleigh-Ritz on it, each checked by its operator residual.
ModalResult solveModes(const ShiftInvertedProblem& problem, const ModalOptions& options);

}  // namespace cyclone::solvers
