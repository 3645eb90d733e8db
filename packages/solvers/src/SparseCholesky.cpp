#include "cyclone/solvers/SparseCholesky.hpp"

#include <Eigen/CholmodSupport>

#include <algorithm>
#include <atomic>
#include <limits>
#include <sstream>
#include <utility>
#include <string>
#include <vector>

#include "cyclone/core/AddressSpace.hpp"
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

// The lower triangle of P A P^T (pinv[old] = new) from the lower triangle of A (an
// upper entry of A is ignored), rows sorted in each column: CHOLMOD then factors it in
// the natural ordering without a permuted copy of its own.
template <class Matrix>
Matrix permutedLower(const Matrix& A, const std::vector<int>& pinv) {
  using Scalar = typename Matrix::Scalar;
  const Eigen::Index n = A.cols();
  std::vector<int> start(std::size_t(n) + 1, 0);
  for (Eigen::Index j = 0; j < n; ++j)
    for (typename Matrix::InnerIterator it(A, j); it; ++it)
      if (it.row() >= j) ++start[std::size_t(std::min(pinv[std::size_t(it.row())], pinv[std::size_t(j)])) + 1];
  for (Eigen::Index j = 0; j < n; ++j) start[std::size_t(j) + 1] += start[std::size_t(j)];
  Matrix B(n, n);
  B.makeCompressed();
  B.resizeNonZeros(start.back());
  std::copy(start.begin(), start.end(), B.outerIndexPtr());
  for (Eigen::Index j = 0; j < n; ++j)
    for (typename Matrix::InnerIterator it(A, j); it; ++it) {
      if (it.row() < j) continue;
      const int r = pinv[std::size_t(it.row())], c = pinv[std::size_t(j)];
      const int at = start[std::size_t(std::min(r, c))]++;
      B.innerIndexPtr()[at] = std::max(r, c);
      B.valuePtr()[at] = r >= c ? it.value() : Scalar(Eigen::numext::conj(it.value()));
    }
  std::vector<std::pair<int, Scalar>> column;
  for (Eigen::Index j = 0; j < n; ++j) {
    const int begin = B.outerIndexPtr()[j], end = B.outerIndexPtr()[j + 1];
    column.clear();
    for (int p = begin; p < end; ++p) column.emplace_back(B.innerIndexPtr()[p], B.valuePtr()[p]);
    std::sort(column.begin(), column.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    for (int p = begin; p < end; ++p) B.innerIndexPtr()[p] = column[std::size_t(p - begin)].first, B.valuePtr()[p] = column[std::size_t(p - begin)].second;
  }
  return B;
}

}  // namespace

std::string cholmodOutOfMemory(long long equations) {
  return "CHOLMOD ran out of memory factoring the matrix (" + std::to_string(equations) +
         " equations): its factor needs more than this machine, or the process's limit (ulimit -v), allows; use a "
         "coarser mesh or more memory";
}

// OpenBLAS's work buffer (kOpenBlasBufferBytes), malloc'd by the first dense kernel a
// supernodal factorization calls, dpotrf, unless takeBlasWorkBuffer had it taken before, and
// kept. Once one factorization has passed, the buffer is held and reused: later ones need
// only their factor (a second buffer, for factorizations on several threads at once, is
// not counted).
static std::atomic<bool> blasBufferTaken{false};

void checkFactorAddressSpace(long long equations, double factorNonzeros, int scalarBytes, bool supernodal) {
  const double left = addressSpaceLeftBytes();
  if (left == std::numeric_limits<double>::infinity()) return;
  // A supernodal factor stores its supernodes' dense blocks: up to about half again the
  // nonzeros cholmod_analyze counts (the relaxed amalgamation's explicit zeros).
  const double factor = 1.5 * factorNonzeros * scalarBytes;
  const double buffer = supernodal && !blasBufferTaken && !blasWorkBufferTaken() ? kOpenBlasBufferBytes : 0.0;
  if (factor + buffer <= left) return;
  const double mb = 1 << 20;
  std::ostringstream why;
  why << std::fixed;
  why.precision(0);
  why << "out of memory before the factorization of the matrix (" << equations << " equations): it needs about "
      << (factor + buffer) / mb << " MB of address space (its factor about " << factor / mb << " MB";
  if (buffer > 0) why << ", OpenBLAS's work buffer " << buffer / mb << " MB";
  why << "), and the process's address-space limit (ulimit -v, " << addressSpaceLimitBytes() / mb << " MB) leaves it "
      << std::max(left, 0.0) / mb
      << " MB: raise the limit, or use a coarser mesh (OpenBLAS, short of room for its buffer, waits forever "
         "instead of failing)";
  throw SolverError(why.str());
}

void noteFactorizationPassed() { blasBufferTaken = true; }

// CHOLMOD's own choice of ordering (AMD, METIS when AMD fills much; then the weighted
// postorder of the elimination tree) is found once on A's pattern, and A is handed over
// permuted, P A P^T, to be factored in the natural ordering: cholmod_factorize otherwise
// makes the permuted copy itself (two, briefly, for a lower triangle) while A is held.
// The solves permute their right-hand sides. Same ordering, same supernodes, same factor.
template <class Scalar>
struct SparseCholesky<Scalar>::Impl {
  CholmodWithEstimate<Matrix> cholmod;
  std::vector<int> outer, inner;  // the analysed pattern (of A, before the permutation)
  std::vector<int> perm, pinv;    // perm[new] = old, pinv[old] = new

  void factorize(const Matrix& B, Eigen::Index equations) {
    cholmod.factorize(B);
    if (cholmod.cholmod().status == CHOLMOD_OUT_OF_MEMORY) throw SolverError(cholmodOutOfMemory(equations));
    if (cholmod.info() != Eigen::Success || !(cholmod.rcond() > 1e-24))
      throw SolverError("CHOLMOD: the matrix (" + std::to_string(equations) +
                        " equations) is not positive definite: a free body without enough constraints, "
                        "a shift above the lowest eigenvalue, or an inverted element");
  }

  // P A P^T factored; A released first when the caller handed it over.
  void permuteAndFactor(const Matrix& A, Matrix* release) {
    Matrix B = permutedLower(A, pinv);
    const Eigen::Index n = A.rows();
    if (release) Matrix().swap(*release);
    factorize(B, n);
  }

  Dense permuted(const Dense& b) const {  // P b
    Dense y(b.rows(), b.cols());
    for (Eigen::Index j = 0; j < b.cols(); ++j)
      for (Eigen::Index i = 0; i < b.rows(); ++i) y(i, j) = b(perm[std::size_t(i)], j);
    return y;
  }
  Dense unpermuted(const Dense& b) const {  // P^T b
    Dense y(b.rows(), b.cols());
    for (Eigen::Index j = 0; j < b.cols(); ++j)
      for (Eigen::Index i = 0; i < b.rows(); ++i) y(perm[std::size_t(i)], j) = b(i, j);
    return y;
  }
};

template <class Scalar>
SparseCholesky<Scalar>::SparseCholesky(const Matrix& A) : SparseCholesky(A, nullptr) {}

template <class Scalar>
SparseCholesky<Scalar>::SparseCholesky(Matrix&& A) : SparseCholesky(A, &A) {}

template <class Scalar>
SparseCholesky<Scalar>::SparseCholesky(const Matrix& A, Matrix* release) : impl_(std::make_unique<Impl>()) {
  auto& I = *impl_;
  auto& c = I.cholmod;
  c.setMode(Eigen::CholmodSupernodalLLt);
  auto& common = c.cholmod();
  common.print = 0;  // failures are reported by SolverError, not on stderr
  I.outer.assign(A.outerIndexPtr(), A.outerIndexPtr() + A.cols() + 1);
  I.inner.assign(A.innerIndexPtr(), A.innerIndexPtr() + A.nonZeros());
  {
    // The ordering alone (a simplicial analysis: no supernodes yet).
    cholmod_sparse view = Eigen::viewAsCholmod(A.template selfadjointView<Eigen::Lower>());
    const int supernodal = common.supernodal;
    common.supernodal = CHOLMOD_SIMPLICIAL;
    cholmod_factor* symbolic = cholmod_analyze(&view, &common);
    common.supernodal = supernodal;
    if (!symbolic) throw SolverError("CHOLMOD: the ordering failed (" + std::to_string(A.rows()) + " equations)");
    const int* p = static_cast<const int*>(symbolic->Perm);
    I.perm.assign(p, p + A.rows());
    cholmod_free_factor(&symbolic, &common);
  }
  I.pinv.resize(I.perm.size());
  for (std::size_t k = 0; k < I.perm.size(); ++k) I.pinv[std::size_t(I.perm[k])] = int(k);
  Matrix B = permutedLower(A, I.pinv);
  if (release) Matrix().swap(*release);
  common.nmethods = 1;
  common.method[0].ordering = CHOLMOD_NATURAL;
  common.postorder = 0;  // already postordered; CHOLMOD would otherwise mark it not natural
  c.analyzePattern(B);
  checkFactorAddressSpace(B.rows(), double(common.lnz), int(sizeof(Scalar)), true);
  I.factorize(B, B.rows());
  noteFactorizationPassed();
}

template <class Scalar>
bool SparseCholesky<Scalar>::refactor(const Matrix& A) {
  if (!samePattern(A)) return false;
  impl_->permuteAndFactor(A, nullptr);
  return true;
}

template <class Scalar>
bool SparseCholesky<Scalar>::refactor(Matrix&& A) {
  if (!samePattern(A)) return false;
  impl_->permuteAndFactor(A, &A);
  return true;
}

template <class Scalar>
bool SparseCholesky<Scalar>::samePattern(const Matrix& A) const {
  const auto& I = *impl_;
  return A.isCompressed() && std::size_t(A.cols()) + 1 == I.outer.size() &&
         std::size_t(A.nonZeros()) == I.inner.size() && std::equal(I.outer.begin(), I.outer.end(), A.outerIndexPtr()) &&
         std::equal(I.inner.begin(), I.inner.end(), A.innerIndexPtr());
}

template <class Scalar>
SparseCholesky<Scalar>::~SparseCholesky() = default;

template <class Scalar>
typename SparseCholesky<Scalar>::Dense SparseCholesky<Scalar>::solve(const Dense& b) const {
  const auto& I = *impl_;
  return I.unpermuted(I.cholmod.solve(I.permuted(b)));
}

// The factor is P A P^T = L L^H (supernodal: always LL^H), P applied here (CHOLMOD's
// own permutation of the natural ordering is the identity).
template <class Scalar>
typename SparseCholesky<Scalar>::Dense SparseCholesky<Scalar>::solveLower(const Dense& b) const {
  auto& c = impl_->cholmod;
  return c.solveSystem(CHOLMOD_L, c.solveSystem(CHOLMOD_P, impl_->permuted(b)));
}

template <class Scalar>
typename SparseCholesky<Scalar>::Dense SparseCholesky<Scalar>::solveUpper(const Dense& b) const {
  auto& c = impl_->cholmod;
  return impl_->unpermuted(c.solveSystem(CHOLMOD_Pt, c.solveSystem(CHOLMOD_Lt, b)));
}

template <class Scalar>
double SparseCholesky<Scalar>::factorNonzeros() const {
  return double(impl_->cholmod.cholmod().lnz);
}

template <class Scalar>
double SparseCholesky<Scalar>::factorFlops() const {
  return impl_->cholmod.cholmod().fl;
}

template <class Scalar>
double SparseCholesky<Scalar>::reciprocalCondition() const {
  return impl_->cholmod.rcond();
}

template class SparseCholesky<double>;
template class SparseCholesky<std::complex<double>>;

}  // namespace cyclone::solvers
