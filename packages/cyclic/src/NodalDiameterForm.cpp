#include "cyclone/cyclic/NodalDiameterForm.hpp"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "cyclone/core/Error.hpp"
#include "cyclone/cyclic/CyclicTransform.hpp"
#include "cyclone/solvers/SparseCholesky.hpp"

namespace cyclone::cyclic {

namespace {

using Real = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;
using Complex = Eigen::SparseMatrix<std::complex<double>, Eigen::ColMajor, int>;

// Per copy of the transform, the map between physical DOFs and unknowns in both
// directions (compressed): byDof[i] the (unknown, t) that DOF i follows,
// byUnknown[q] the (DOF, t) that unknown q moves.
template <class Scalar>
struct Coupling {
  struct Entry {
    int index;
    Scalar value;
  };
  std::vector<int> dofStart, unknownStart;
  std::vector<Entry> byDof, byUnknown;
};

template <class Scalar>
Coupling<Scalar> compress(std::vector<std::vector<typename Coupling<Scalar>::Entry>> perDof, int unknowns) {
  Coupling<Scalar> c;
  c.dofStart.push_back(0);
  std::vector<int> count(std::size_t(unknowns) + 1, 0);
  for (const auto& list : perDof) {
    c.byDof.insert(c.byDof.end(), list.begin(), list.end());
    c.dofStart.push_back(int(c.byDof.size()));
    for (const auto& e : list) ++count[std::size_t(e.index) + 1];
  }
  for (int q = 0; q < unknowns; ++q) count[std::size_t(q) + 1] += count[std::size_t(q)];
  c.unknownStart = count;
  c.byUnknown.resize(c.byDof.size());
  for (std::size_t i = 0; i < perDof.size(); ++i)
    for (const auto& e : perDof[i]) c.byUnknown[std::size_t(count[std::size_t(e.index)]++)] = {int(i), e.value};
  return c;
}

// Copy `copy` of the transform, real coefficients on the transform's unknowns.
Coupling<double> realCoupling(const fe::DofTransform& T, int copy) {
  std::vector<std::vector<Coupling<double>::Entry>> perDof(std::size_t(3 * T.numNodes()));
  for (mesh::Index n = 0; n < T.numNodes(); ++n)
    for (int d = 0; d < 3; ++d)
      for (const auto& t : T.terms(n, d, copy)) perDof[std::size_t(3 * n + d)].push_back({int(t.equation), t.coefficient});
  return compress<double>(std::move(perDof), int(T.numEquations()));
}

// The complex transform of a paired one, u_a + i u_b = sum_m t_m z_m: copy a of u is
// Re(t z) = Re t x_2m - Im t x_2m+1, so t = alpha - i beta with alpha, beta the
// coefficients of x_2m and x_2m+1 in copy a.
Coupling<std::complex<double>> complexCoupling(const fe::DofTransform& T) {
  using Entry = Coupling<std::complex<double>>::Entry;
  std::vector<std::vector<Entry>> perDof(std::size_t(3 * T.numNodes()));
  for (mesh::Index n = 0; n < T.numNodes(); ++n)
    for (int d = 0; d < 3; ++d) {
      auto& list = perDof[std::size_t(3 * n + d)];
      for (const auto& t : T.terms(n, d, 0)) {
        const int m = int(t.equation / 2);
        const std::complex<double> part = t.equation % 2 == 0 ? std::complex<double>(t.coefficient, 0.0)
                                                              : std::complex<double>(0.0, -t.coefficient);
        auto it = std::find_if(list.begin(), list.end(), [&](const Entry& e) { return e.index == m; });
        if (it == list.end()) list.push_back({m, part});
        else it->value += part;
      }
    }
  return compress<std::complex<double>>(std::move(perDof), int(T.numEquations() / 2));
}

double conjugate(double x) { return x; }
std::complex<double> conjugate(const std::complex<double>& z) { return std::conj(z); }

// The lower triangles of T^H K T and T^H M T summed over the copies, in one pass over
// the sector's columns
// (Gustavson's scatter: column q of the result gathers, for every DOF j that q moves,
// column j of K and M mapped onto the unknowns its rows follow). K and M share one
// pattern. The result keeps the structural pattern (no entry dropped for being zero),
// so every nodal diameter of one kind gets the same pattern and the same symbolic
// factorization. ZK or ZM may be null (not formed); normMSquared, when given, gets the
// squared Frobenius norm of the Hermitian T^H M T whether ZM is formed or not.
template <class Scalar>
void project(const SectorMatrices& sector, const std::vector<Coupling<Scalar>>& copies, int unknowns,
             Eigen::SparseMatrix<Scalar, Eigen::ColMajor, int>* ZK, Eigen::SparseMatrix<Scalar, Eigen::ColMajor, int>* ZM,
             double* normMSquared = nullptr) {
  const double* k = sector.k.data();
  const double* m = sector.m.data();
  // Every (row u >= q, entry p of the sector's matrices, coefficient s t) that column q gathers.
  auto gather = [&](int q, auto&& visit) {
    for (const auto& c : copies)
      for (int a = c.unknownStart[std::size_t(q)]; a < c.unknownStart[std::size_t(q) + 1]; ++a) {
        const auto& [j, t] = c.byUnknown[std::size_t(a)];
        sector.forEachInColumn(j, [&](int i, int p) {
          for (int b = c.dofStart[std::size_t(i)]; b < c.dofStart[std::size_t(i) + 1]; ++b) {
            const auto& [u, s] = c.byDof[std::size_t(b)];
            if (u >= q) visit(u, p, conjugate(s) * t);  // the lower triangle only: the forms are Hermitian
          }
        });
      }
  };
  // First the pattern, then the values into matrices of exactly its size: no temporary
  // copy of the result (110 MB at the peak of the built-in sector at mesh size 2.8).
  std::vector<int> seenIn(std::size_t(unknowns), -1), rows, start(1, 0), index;
  for (int q = 0; q < unknowns; ++q) {
    rows.clear();
    gather(q, [&](int u, int, const Scalar&) {
      if (seenIn[std::size_t(u)] != q) seenIn[std::size_t(u)] = q, rows.push_back(u);
    });
    std::sort(rows.begin(), rows.end());
    index.insert(index.end(), rows.begin(), rows.end());
    start.push_back(int(index.size()));
  }
  for (auto* Z : {ZK, ZM}) {
    if (!Z) continue;
    Z->resize(unknowns, unknowns);
    Z->makeCompressed();
    Z->resizeNonZeros(Eigen::Index(index.size()));
    std::copy(start.begin(), start.end(), Z->outerIndexPtr());
    std::copy(index.begin(), index.end(), Z->innerIndexPtr());
  }
  std::vector<Scalar> sumK(static_cast<std::size_t>(unknowns)), sumM(static_cast<std::size_t>(unknowns));
  for (int q = 0; q < unknowns; ++q) {
    for (int e = start[std::size_t(q)]; e < start[std::size_t(q) + 1]; ++e)
      sumK[std::size_t(index[std::size_t(e)])] = sumM[std::size_t(index[std::size_t(e)])] = Scalar(0);
    gather(q, [&](int u, int p, const Scalar& st) {
      sumK[std::size_t(u)] += st * k[p];
      sumM[std::size_t(u)] += st * m[p];
    });
    for (int e = start[std::size_t(q)]; e < start[std::size_t(q) + 1]; ++e) {
      const int u = index[std::size_t(e)];
      if (ZK) ZK->valuePtr()[e] = sumK[std::size_t(u)];
      if (ZM) ZM->valuePtr()[e] = sumM[std::size_t(u)];
      if (normMSquared) *normMSquared += (u == q ? 1.0 : 2.0) * std::norm(sumM[std::size_t(u)]);
    }
  }
}

// y = A x for a Hermitian A stored as its lower triangle, every column of x in one
// pass over A (the product is bound by reading A).
template <class Scalar>
void hermitianProduct(const Eigen::SparseMatrix<Scalar, Eigen::ColMajor, int>& A, const Scalar* x, Scalar* y,
                      Eigen::Index columns) {
  const Eigen::Index n = A.rows();
  const int* outer = A.outerIndexPtr();
  const int* inner = A.innerIndexPtr();
  const Scalar* value = A.valuePtr();
  std::fill(y, y + n * columns, Scalar(0));
  for (Eigen::Index c = 0; c < n; ++c)
    for (int p = outer[c]; p < outer[c + 1]; ++p) {
      const Eigen::Index r = inner[p];
      const Scalar a = value[p];
      for (Eigen::Index j = 0; j < columns; ++j) {
        y[j * n + r] += a * x[j * n + c];
        if (r != c) y[j * n + c] += conjugate(a) * x[j * n + r];
      }
    }
}

// The real-form unknowns (x_2m, x_2m+1) = (Re z_m, Im z_m) are the memory layout of a
// complex column, so a real-form block is read and written as complex in place.
const std::complex<double>* asComplex(const Eigen::MatrixXd& x) {
  return reinterpret_cast<const std::complex<double>*>(x.data());
}
std::complex<double>* asComplex(Eigen::MatrixXd& x) { return reinterpret_cast<std::complex<double>*>(x.data()); }

// Frobenius norm of a Hermitian matrix from its lower triangle.
template <class Matrix>
double hermitianNorm(const Matrix& lower) {
  double sum = 0;
  for (Eigen::Index c = 0; c < lower.outerSize(); ++c)
    for (typename Matrix::InnerIterator it(lower, c); it; ++it)
      sum += (it.row() == it.col() ? 1.0 : 2.0) * std::norm(it.value());
  return std::sqrt(sum);
}

}  // namespace

struct FactorCache::Impl {
  std::unique_ptr<solvers::SparseCholesky<double>> real;
  std::unique_ptr<solvers::SparseCholesky<std::complex<double>>> complex;
};

FactorCache::FactorCache() : impl_(std::make_unique<Impl>()) {}
FactorCache::~FactorCache() = default;

namespace {

// A factor of A, the cached one refactored when A has its pattern. A is handed over:
// its storage is released once CHOLMOD's permuted copy is made, before the numeric
// factorization.
template <class Scalar, class Matrix>
void factorInto(std::unique_ptr<solvers::SparseCholesky<Scalar>>& slot, Matrix&& A) {
  try {
    if (slot && slot->refactor(std::move(A))) return;
  } catch (...) {
    slot.reset();  // a failed numeric factorization leaves no usable factor
    throw;
  }
  slot.reset();  // free the old factor before the new one is built
  slot = std::make_unique<solvers::SparseCholesky<Scalar>>(std::move(A));
}

}  // namespace

struct NodalDiameterForm::Impl {
  bool complexForm = false;
  long long size = 0;
  Real K, M;      // real form, lower triangles
  Complex ZK, ZM; // complex form, lower triangles
  double normK = 0, normM = 0;
  FactorCache own;
  FactorCache::Impl* factors = nullptr;  // own's or a caller's
  // After releaseProjections: the products through the sector's matrices.
  const SectorMatrices* sector = nullptr;
  std::vector<Coupling<double>> realCouplings;
  Coupling<std::complex<double>> complexCoupling;
  bool released = false;
};

namespace {

// y = T^H A T x for one column, T given by a coupling: u = T x gathered per DOF, w = A u
// (A real, both triangles), y scattered per unknown with the conjugate coefficients;
// added into y.
template <class Scalar>
void productThroughSector(const SectorMatrices& sector, const std::vector<double>& A, const Coupling<Scalar>& c,
                          const Scalar* x, Scalar* y, std::vector<Scalar>& u, std::vector<Scalar>& w) {
  const std::size_t dofs = std::size_t(sector.dofs());
  u.assign(dofs, Scalar(0));
  w.resize(dofs);
  for (std::size_t i = 0; i < dofs; ++i)
    for (int b = c.dofStart[i]; b < c.dofStart[i + 1]; ++b)
      u[i] += c.byDof[std::size_t(b)].value * x[c.byDof[std::size_t(b)].index];
  sector.multiply(A, u.data(), w.data());
  const std::size_t unknowns = c.unknownStart.size() - 1;
  for (std::size_t q = 0; q < unknowns; ++q) {
    Scalar sum(0);
    for (int a = c.unknownStart[q]; a < c.unknownStart[q + 1]; ++a)
      sum += conjugate(c.byUnknown[std::size_t(a)].value) * w[std::size_t(c.byUnknown[std::size_t(a)].index)];
    y[q] += sum;
  }
}

}  // namespace

NodalDiameterForm::NodalDiameterForm(const SectorMatrices& sector, const fe::DofTransform& transform)
    : impl_(std::make_unique<Impl>()) {
  auto& I = *impl_;
  I.size = transform.numEquations();
  I.complexForm = transform.copies() == 2 && travellingWavePaired(transform);
  I.sector = &sector;
  if (I.complexForm) {
    I.complexCoupling = complexCoupling(transform);
    // Only K is formed: M is applied through the sector's matrices (and formed only for
    // a shifted factor), so the factorization's peak does not hold it.
    double normM2 = 0;
    project<std::complex<double>>(sector, {I.complexCoupling}, int(I.size / 2), &I.ZK, nullptr, &normM2);
    // The real form [[P, -Q], [Q, P]] holds every entry of P + iQ twice.
    I.normK = std::sqrt(2.0) * hermitianNorm(I.ZK), I.normM = std::sqrt(2.0 * normM2);
    return;
  }
  for (int copy = 0; copy < transform.copies(); ++copy) I.realCouplings.push_back(realCoupling(transform, copy));
  double normM2 = 0;
  project<double>(sector, I.realCouplings, int(I.size), &I.K, nullptr, &normM2);
  I.normK = hermitianNorm(I.K), I.normM = std::sqrt(normM2);
}

NodalDiameterForm::~NodalDiameterForm() = default;
NodalDiameterForm::NodalDiameterForm(NodalDiameterForm&&) noexcept = default;
NodalDiameterForm& NodalDiameterForm::operator=(NodalDiameterForm&&) noexcept = default;

bool NodalDiameterForm::complexForm() const { return impl_->complexForm; }
long long NodalDiameterForm::size() const { return impl_->size; }

namespace {

void applyThroughSector(bool complexForm, const Coupling<std::complex<double>>& complexCoupling,
                        const std::vector<Coupling<double>>& realCouplings, const SectorMatrices& sector,
                        const std::vector<double>& A, const Eigen::MatrixXd& x, Eigen::MatrixXd& y) {
  y.setZero(x.rows(), x.cols());
  if (complexForm) {
    std::vector<std::complex<double>> u, w;
    const Eigen::Index n = x.rows() / 2;
    for (Eigen::Index j = 0; j < x.cols(); ++j)
      productThroughSector(sector, A, complexCoupling, asComplex(x) + j * n, asComplex(y) + j * n, u, w);
    return;
  }
  std::vector<double> u, w;
  for (Eigen::Index j = 0; j < x.cols(); ++j)
    for (const auto& c : realCouplings) productThroughSector(sector, A, c, x.data() + j * x.rows(), y.data() + j * x.rows(), u, w);
}

}  // namespace

void NodalDiameterForm::applyK(const Eigen::MatrixXd& x, Eigen::MatrixXd& y) const {
  const auto& I = *impl_;
  // K is handed to the factor at sigma = 0 (not kept beside it).
  if (I.released || (I.complexForm ? I.ZK.nonZeros() == 0 : I.K.nonZeros() == 0)) return applyThroughSector(I.complexForm, I.complexCoupling, I.realCouplings, *I.sector, I.sector->k, x, y);
  y.resize(x.rows(), x.cols());
  if (impl_->complexForm) hermitianProduct(impl_->ZK, asComplex(x), asComplex(y), x.cols());
  else hermitianProduct(impl_->K, x.data(), y.data(), x.cols());
}

void NodalDiameterForm::applyM(const Eigen::MatrixXd& x, Eigen::MatrixXd& y) const {
  const auto& I = *impl_;
  // M is formed only for a shifted factor, and then only until the projections are released.
  if (I.released || (I.complexForm ? I.ZM.nonZeros() == 0 : I.M.nonZeros() == 0))
    return applyThroughSector(I.complexForm, I.complexCoupling, I.realCouplings, *I.sector, I.sector->m, x, y);
  y.resize(x.rows(), x.cols());
  if (impl_->complexForm) hermitianProduct(impl_->ZM, asComplex(x), asComplex(y), x.cols());
  else hermitianProduct(impl_->M, x.data(), y.data(), x.cols());
}

void NodalDiameterForm::releaseProjections() {
  auto& I = *impl_;
  if (!I.factors) throw Error("NodalDiameterForm::releaseProjections: factor first");
  I.K = Real(), I.M = Real(), I.ZK = Complex(), I.ZM = Complex();
  I.released = true;
}

void NodalDiameterForm::timesI(const Eigen::MatrixXd& x, Eigen::MatrixXd& y) const {
  y.resize(x.rows(), x.cols());
  for (Eigen::Index m = 0; 2 * m + 1 < x.rows(); ++m) {
    y.row(2 * m) = -x.row(2 * m + 1);
    y.row(2 * m + 1) = x.row(2 * m);
  }
}

double NodalDiameterForm::normK() const { return impl_->normK; }
double NodalDiameterForm::normM() const { return impl_->normM; }

void NodalDiameterForm::factor(double sigma) { factor(sigma, impl_->own); }

void NodalDiameterForm::factor(double sigma, FactorCache& cache) {
  auto& I = *impl_;
  I.factors = nullptr;
  auto& slots = *cache.impl_;
  // One factor at a time: the other kind's (a real nodal diameter's among pairs) goes.
  if (I.complexForm) slots.real.reset();
  else slots.complex.reset();
  // At sigma = 0 (a constrained sector, the usual case) K itself, handed over: released
  // once CHOLMOD has its permuted copy, so the factorization holds one copy of K.
  if (I.released) throw Error("NodalDiameterForm::factor: the projections were released");
  // K went to an earlier factor (at sigma = 0): projected again.
  if (I.complexForm && I.ZK.nonZeros() == 0)
    project<std::complex<double>>(*I.sector, {I.complexCoupling}, int(I.size / 2), &I.ZK, nullptr);
  if (!I.complexForm && I.K.nonZeros() == 0)
    project<double>(*I.sector, I.realCouplings, int(I.size), &I.K, nullptr);
  // A shift needs M formed: projected now (the same pattern as K).
  if (sigma != 0.0) {
    if (I.complexForm && I.ZM.nonZeros() == 0)
      project<std::complex<double>>(*I.sector, {I.complexCoupling}, int(I.size / 2), nullptr, &I.ZM);
    if (!I.complexForm && I.M.nonZeros() == 0)
      project<double>(*I.sector, I.realCouplings, int(I.size), nullptr, &I.M);
  }
  if (I.complexForm) {
    if (sigma == 0.0) factorInto(slots.complex, std::move(I.ZK));
    else factorInto(slots.complex, Complex(I.ZK - sigma * I.ZM));
  } else {
    if (sigma == 0.0) factorInto(slots.real, std::move(I.K));
    else factorInto(slots.real, Real(I.K - sigma * I.M));
  }
  I.factors = &slots;
}

bool NodalDiameterForm::factored() const { return impl_->factors != nullptr; }

namespace {

// `solve` of a factor applied to a real-form block, read and written as complex in place
// in complex form.
template <class RealSolve, class ComplexSolve>
void solveBlock(bool complexForm, const Eigen::MatrixXd& x, Eigen::MatrixXd& y, RealSolve real, ComplexSolve complex) {
  y.resize(x.rows(), x.cols());
  if (complexForm) {
    const Eigen::Index n = x.rows() / 2;
    const Eigen::Map<const Eigen::MatrixXcd> z(asComplex(x), n, x.cols());
    Eigen::Map<Eigen::MatrixXcd>(asComplex(y), n, x.cols()) = complex(Eigen::MatrixXcd(z));
  } else {
    y = real(x);
  }
}

}  // namespace

void NodalDiameterForm::solveShifted(const Eigen::MatrixXd& x, Eigen::MatrixXd& y) const {
  const auto& f = *impl_->factors;
  solveBlock(impl_->complexForm, x, y, [&](const Eigen::MatrixXd& b) { return f.real->solve(b); },
             [&](const Eigen::MatrixXcd& b) { return f.complex->solve(b); });
}

void NodalDiameterForm::solveLower(const Eigen::MatrixXd& x, Eigen::MatrixXd& y) const {
  const auto& f = *impl_->factors;
  solveBlock(impl_->complexForm, x, y, [&](const Eigen::MatrixXd& b) { return f.real->solveLower(b); },
             [&](const Eigen::MatrixXcd& b) { return f.complex->solveLower(b); });
}

void NodalDiameterForm::solveUpper(const Eigen::MatrixXd& x, Eigen::MatrixXd& y) const {
  const auto& f = *impl_->factors;
  solveBlock(impl_->complexForm, x, y, [&](const Eigen::MatrixXd& b) { return f.real->solveUpper(b); },
             [&](const Eigen::MatrixXcd& b) { return f.complex->solveUpper(b); });
}

double NodalDiameterForm::factorNonzeros() const {
  if (!impl_->factors) return 0.0;
  return impl_->complexForm ? impl_->factors->complex->factorNonzeros() : impl_->factors->real->factorNonzeros();
}

}  // namespace cyclone::cyclic
