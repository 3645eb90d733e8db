#pragma once
// CHOLMOD's supernodal Cholesky (METIS ordering, OpenBLAS) of a real symmetric or
// complex Hermitian positive definite sparse matrix held in Eigen, on one process:
// the factor behind the cyclic sector's shift-invert eigen-solution, where each
// nodal diameter's complex Hermitian operator (half the size of its real form)
// is factored once. DirectSolver is the distributed (Tpetra, gathered) front end.
#include <complex>
#include <memory>

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
  ~SparseCholesky();
  SparseCholesky(const SparseCholesky&) = delete;
  SparseCholesky& operator=(const SparseCholesky&) = delete;

  /// A^{-1} b, all columns at once.
  Dense solve(const Dense& b) const;

  double factorNonzeros() const;  ///< nnz(L)
  double factorFlops() const;     ///< CHOLMOD's flop count of the factorization

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

extern template class SparseCholesky<double>;
extern template class SparseCholesky<std::complex<double>>;

}  // namespace cyclone::solvers
