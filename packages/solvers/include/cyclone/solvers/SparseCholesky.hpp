#pragma once
// CHOLMOD's supernodal Cholesky (METIS ordering, OpenBLAS) of a real symmetric or
// complex Hermitian positive definite sparse matrix held in Eigen, on one process:
// the factor behind the cyclic sector's shift-invert eigen-solution, where each
// nodal diameter's complex Hermitian operator (half the size of its real form)
// is factored once. DirectSolver is the distributed (Tpetra, gathered) front end.
#include <complex>
#include <memory>
#include <string>

#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace cyclone::solvers {

template <class Scalar>
class SparseCholesky {
public:
  using Matrix = Eigen::SparseMatrix<Scalar, Eigen::ColMajor, int>;
  using Dense = Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>;

  /// Factors A (only its lower triangle is read). Throws SolverError when A is not
  /// positive definite (including a factor whose pivots span more than 1e24).
  explicit SparseCholesky(const Matrix& A);
  /// The same, A's storage released once its permuted copy is made (before the
  /// numeric factorization, whose peak then holds one copy of the matrix, not two).
  explicit SparseCholesky(Matrix&& A);
  ~SparseCholesky();
  SparseCholesky(const SparseCholesky&) = delete;
  SparseCholesky& operator=(const SparseCholesky&) = delete;

  /// Factors A again with the symbolic analysis (ordering, supernodes) of the first
  /// matrix, when A has exactly its pattern (compressed); false, and nothing changed,
  /// otherwise. Throws SolverError like the constructor.
  bool refactor(const Matrix& A);
  /// The same, releasing A as the constructor does when it is refactored (A is left
  /// untouched when false).
  bool refactor(Matrix&& A);

  /// A^{-1} b, all columns at once.
  Dense solve(const Dense& b) const;
  /// The halves of the solve, with the factor P A P^T = L L^H (P the fill-reducing
  /// permutation): L^{-1} P b and P^T L^{-H} b, so that A^{-1} = solveUpper(solveLower).
  /// They turn a generalized eigenproblem into a standard one, L^{-1} P M P^T L^{-H}.
  Dense solveLower(const Dense& b) const;
  Dense solveUpper(const Dense& b) const;

  double factorNonzeros() const;  ///< nnz(L)
  double factorFlops() const;     ///< CHOLMOD's flop count of the factorization
  double reciprocalCondition() const;  ///< CHOLMOD's estimate (min/max pivot, squared for LL^H)

private:
  SparseCholesky(const Matrix& A, Matrix* release);
  bool samePattern(const Matrix& A) const;
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

extern template class SparseCholesky<double>;
extern template class SparseCholesky<std::complex<double>>;

/// What CHOLMOD's out-of-memory status means for a user (a SolverError's text): its
/// partial factor otherwise reads as a matrix that is not positive definite.
std::string cholmodOutOfMemory(long long equations);

/// Before a factorization: SolverError where the process's address-space limit (ulimit
/// -v) leaves less room than the factor (`factorNonzeros` entries of `scalarBytes`, as
/// cholmod_analyze counts them) and, for a supernodal factor, OpenBLAS's work buffer
/// need. Short of room for that buffer OpenBLAS waits forever instead of failing (the
/// demo's disc under `ulimit -v 600000` hung in its first factorization), so the shortfall
/// is said before it. Nothing is checked without a limit.
void checkFactorAddressSpace(long long equations, double factorNonzeros, int scalarBytes, bool supernodal);

/// After a supernodal factorization passed: OpenBLAS holds its work buffer from then on,
/// and checkFactorAddressSpace counts only the factors.
void noteFactorizationPassed();

}  // namespace cyclone::solvers
