#include "cyclone/solvers/SparseCholesky.hpp"

#include <Eigen/CholmodSupport>

#include <string>

#include "cyclone/core/Error.hpp"

namespace cyclone::solvers {

namespace {

// CHOLMOD's reciprocal condition estimate (min/max pivot of the factor): a matrix that is
// singular to round-off can factor "successfully", which this exposes.
template <class Matrix>
struct CholmodWithEstimate : Eigen::CholmodDecomposition<Matrix, Eigen::Lower> {
  double rcond() { return this->m_cholmodFactor ? cholmod_rcond(this->m_cholmodFactor, &this->cholmod()) : 0.0; }
};

}  // namespace

template <class Scalar>
struct SparseCholesky<Scalar>::Impl {
  CholmodWithEstimate<Matrix> cholmod;
};

template <class Scalar>
SparseCholesky<Scalar>::SparseCholesky(const Matrix& A) : impl_(std::make_unique<Impl>()) {
  auto& c = impl_->cholmod;
  c.setMode(Eigen::CholmodSupernodalLLt);
  c.cholmod().print = 0;  // failures are reported by SolverError, not on stderr
  c.compute(A);
  if (c.info() != Eigen::Success || !(c.rcond() > 1e-24))
    throw SolverError("CHOLMOD: the matrix (" + std::to_string(A.rows()) +
                      " equations) is not positive definite: a free body without enough constraints, "
                      "a shift above the lowest eigenvalue, or an inverted element");
}

template <class Scalar>
SparseCholesky<Scalar>::~SparseCholesky() = default;

template <class Scalar>
typename SparseCholesky<Scalar>::Dense SparseCholesky<Scalar>::solve(const Dense& b) const {
  return impl_->cholmod.solve(b);
}

template <class Scalar>
double SparseCholesky<Scalar>::factorNonzeros() const {
  return double(impl_->cholmod.cholmod().lnz);
}

template <class Scalar>
double SparseCholesky<Scalar>::factorFlops() const {
  return impl_->cholmod.cholmod().fl;
}

template class SparseCholesky<double>;
template class SparseCholesky<std::complex<double>>;

}  // namespace cyclone::solvers
