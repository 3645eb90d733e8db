#include "cyclone/solvers/SparseCholesky.hpp"

#include <Eigen/CholmodSupport>

#include <algorithm>
#include <string>
#include <vector>

#include "cyclone/core/Error.hpp"

namespace cyclone::solvers {

namespace {

// CHOLMOD's reciprocal condition estimate (min/max pivot of the factor): a matrix that is
// singular to round-off can factor "successfully", which this exposes.
template <class Matrix>
struct CholmodWithEstimate : Eigen::CholmodDecomposition<Matrix, Eigen::Lower> {
  double rcond() { return this->m_cholmodFactor ? cholmod_rcond(this->m_cholmodFactor, &this->cholmod()) : 0.0; }

  // CHOLMOD's solve with system `sys` (CHOLMOD_P, CHOLMOD_L, CHOLMOD_Lt, CHOLMOD_Pt, ...).
  template <class Dense>
  Dense solveSystem(int sys, const Dense& b) {
    Eigen::Ref<const Dense> view(b);
    cholmod_dense in = Eigen::viewAsCholmod(view);
    cholmod_dense* out = cholmod_solve(sys, this->m_cholmodFactor, &in, &this->cholmod());
    if (!out) throw SolverError("CHOLMOD: a triangular solve failed");
    Dense x = Eigen::Map<const Dense>(reinterpret_cast<const typename Dense::Scalar*>(out->x), b.rows(), b.cols());
    cholmod_free_dense(&out, &this->cholmod());
    return x;
  }
};

}  // namespace

template <class Scalar>
struct SparseCholesky<Scalar>::Impl {
  CholmodWithEstimate<Matrix> cholmod;
  std::vector<int> outer, inner;  // the analysed pattern

  void factorize(const Matrix& A) {
    cholmod.factorize(A);
    if (cholmod.info() != Eigen::Success || !(cholmod.rcond() > 1e-24))
      throw SolverError("CHOLMOD: the matrix (" + std::to_string(A.rows()) +
                        " equations) is not positive definite: a free body without enough constraints, "
                        "a shift above the lowest eigenvalue, or an inverted element");
  }
};

template <class Scalar>
SparseCholesky<Scalar>::SparseCholesky(const Matrix& A) : impl_(std::make_unique<Impl>()) {
  auto& c = impl_->cholmod;
  c.setMode(Eigen::CholmodSupernodalLLt);
  c.cholmod().print = 0;  // failures are reported by SolverError, not on stderr
  impl_->outer.assign(A.outerIndexPtr(), A.outerIndexPtr() + A.cols() + 1);
  impl_->inner.assign(A.innerIndexPtr(), A.innerIndexPtr() + A.nonZeros());
  c.analyzePattern(A);
  impl_->factorize(A);
}

template <class Scalar>
bool SparseCholesky<Scalar>::refactor(const Matrix& A) {
  auto& I = *impl_;
  if (!A.isCompressed() || std::size_t(A.cols()) + 1 != I.outer.size() ||
      std::size_t(A.nonZeros()) != I.inner.size() ||
      !std::equal(I.outer.begin(), I.outer.end(), A.outerIndexPtr()) ||
      !std::equal(I.inner.begin(), I.inner.end(), A.innerIndexPtr()))
    return false;
  I.factorize(A);
  return true;
}

template <class Scalar>
SparseCholesky<Scalar>::~SparseCholesky() = default;

template <class Scalar>
typename SparseCholesky<Scalar>::Dense SparseCholesky<Scalar>::solve(const Dense& b) const {
  return impl_->cholmod.solve(b);
}

// The factor is P A P^T = L L^H (supernodal: always LL^H).
template <class Scalar>
typename SparseCholesky<Scalar>::Dense SparseCholesky<Scalar>::solveLower(const Dense& b) const {
  return impl_->cholmod.solveSystem(CHOLMOD_L, impl_->cholmod.solveSystem(CHOLMOD_P, b));
}

template <class Scalar>
typename SparseCholesky<Scalar>::Dense SparseCholesky<Scalar>::solveUpper(const Dense& b) const {
  return impl_->cholmod.solveSystem(CHOLMOD_Pt, impl_->cholmod.solveSystem(CHOLMOD_Lt, b));
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
