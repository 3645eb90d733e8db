#include "cyclone/cyclic/HarmonicForm.hpp"

#include <cmath>
#include <vector>

#include "cyclone/cyclic/CyclicTransform.hpp"
#include "cyclone/solvers/SparseCholesky.hpp"

namespace cyclone::cyclic {

namespace {

using Real = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;
using Complex = Eigen::SparseMatrix<std::complex<double>, Eigen::ColMajor, int>;

// Copy `copy` of the transform as a sparse 3n x equations matrix.
Real copyMatrix(const fe::DofTransform& T, int copy) {
  std::vector<Eigen::Triplet<double, int>> entries;
  for (mesh::Index n = 0; n < T.numNodes(); ++n)
    for (int d = 0; d < 3; ++d)
      for (const auto& t : T.terms(n, d, copy)) entries.emplace_back(int(3 * n + d), int(t.equation), t.coefficient);
  Real out(int(3 * T.numNodes()), int(T.numEquations()));
  out.setFromTriplets(entries.begin(), entries.end());
  return out;
}

// The complex transform of a paired one, u_a + i u_b = sum_m t_m z_m, split as
// Re + i Im: copy a of u is Re(t z) = Re t x_2m - Im t x_2m+1, so t = alpha - i beta
// with alpha, beta the coefficients of x_2m and x_2m+1 in copy a.
void complexTransform(const fe::DofTransform& T, Real& re, Real& im) {
  std::vector<Eigen::Triplet<double, int>> a, b;
  for (mesh::Index n = 0; n < T.numNodes(); ++n)
    for (int d = 0; d < 3; ++d)
      for (const auto& t : T.terms(n, d, 0)) {
        const int row = int(3 * n + d), column = int(t.equation / 2);
        if (t.equation % 2 == 0) a.emplace_back(row, column, t.coefficient);
        else b.emplace_back(row, column, -t.coefficient);
      }
  const int rows = int(3 * T.numNodes()), columns = int(T.numEquations() / 2);
  re.resize(rows, columns);
  im.resize(rows, columns);
  re.setFromTriplets(a.begin(), a.end());
  im.setFromTriplets(b.begin(), b.end());
}

// T^H A T = (Re^T A Re + Im^T A Im) + i (Re^T A Im - Im^T A Re) for a real symmetric A.
Complex projectComplex(const Real& A, const Real& re, const Real& im) {
  const Real Are = A * re, Aim = A * im;
  const Real ret = re.transpose(), imt = im.transpose();
  const Real realPart = ret * Are + imt * Aim;
  const Real imagPart = ret * Aim - imt * Are;
  Complex Z = realPart.cast<std::complex<double>>() + std::complex<double>(0, 1) * imagPart.cast<std::complex<double>>();
  Z.prune([](const Eigen::Index&, const Eigen::Index&, const std::complex<double>& v) { return v != 0.0; });
  return Z;
}

Eigen::MatrixXcd toComplex(const Eigen::MatrixXd& x) {
  Eigen::MatrixXcd z(x.rows() / 2, x.cols());
  for (Eigen::Index j = 0; j < x.cols(); ++j)
    for (Eigen::Index m = 0; m < z.rows(); ++m) z(m, j) = {x(2 * m, j), x(2 * m + 1, j)};
  return z;
}

void toReal(const Eigen::MatrixXcd& z, Eigen::MatrixXd& x) {
  x.resize(2 * z.rows(), z.cols());
  for (Eigen::Index j = 0; j < z.cols(); ++j)
    for (Eigen::Index m = 0; m < z.rows(); ++m) {
      x(2 * m, j) = z(m, j).real();
      x(2 * m + 1, j) = z(m, j).imag();
    }
}

}  // namespace

struct HarmonicForm::Impl {
  bool complexForm = false;
  long long size = 0;
  Real K, M;      // real form
  Complex ZK, ZM; // complex form
  std::unique_ptr<solvers::SparseCholesky<double>> realFactor;
  std::unique_ptr<solvers::SparseCholesky<std::complex<double>>> complexFactor;
};

HarmonicForm::HarmonicForm(const SectorMatrices& sector, const fe::DofTransform& transform)
    : impl_(std::make_unique<Impl>()) {
  auto& I = *impl_;
  I.size = transform.numEquations();
  I.complexForm = transform.copies() == 2 && travellingWavePaired(transform);
  if (I.complexForm) {
    Real re, im;
    complexTransform(transform, re, im);
    I.ZK = projectComplex(sector.K, re, im);
    I.ZM = projectComplex(sector.M, re, im);
    return;
  }
  for (int copy = 0; copy < transform.copies(); ++copy) {
    const Real T = copyMatrix(transform, copy);
    const Real Tt = T.transpose();
    const Real K = Tt * (sector.K * T), M = Tt * (sector.M * T);
    if (copy == 0) I.K = K, I.M = M;
    else I.K += K, I.M += M;
  }
}

HarmonicForm::~HarmonicForm() = default;
HarmonicForm::HarmonicForm(HarmonicForm&&) noexcept = default;
HarmonicForm& HarmonicForm::operator=(HarmonicForm&&) noexcept = default;

bool HarmonicForm::complexForm() const { return impl_->complexForm; }
long long HarmonicForm::size() const { return impl_->size; }

void HarmonicForm::applyK(const Eigen::MatrixXd& x, Eigen::MatrixXd& y) const {
  if (impl_->complexForm) toReal(impl_->ZK * toComplex(x), y);
  else y = impl_->K * x;
}

void HarmonicForm::applyM(const Eigen::MatrixXd& x, Eigen::MatrixXd& y) const {
  if (impl_->complexForm) toReal(impl_->ZM * toComplex(x), y);
  else y = impl_->M * x;
}

void HarmonicForm::timesI(const Eigen::MatrixXd& x, Eigen::MatrixXd& y) const {
  y.resize(x.rows(), x.cols());
  for (Eigen::Index m = 0; 2 * m + 1 < x.rows(); ++m) {
    y.row(2 * m) = -x.row(2 * m + 1);
    y.row(2 * m + 1) = x.row(2 * m);
  }
}

// The real form [[P, -Q], [Q, P]] holds every entry of P + iQ twice.
double HarmonicForm::normK() const { return impl_->complexForm ? std::sqrt(2.0) * impl_->ZK.norm() : impl_->K.norm(); }
double HarmonicForm::normM() const { return impl_->complexForm ? std::sqrt(2.0) * impl_->ZM.norm() : impl_->M.norm(); }

void HarmonicForm::factor(double sigma) {
  auto& I = *impl_;
  I.realFactor.reset();
  I.complexFactor.reset();
  // At sigma = 0 (a constrained sector, the usual case) K itself, without a copy.
  if (I.complexForm)
    I.complexFactor = std::make_unique<solvers::SparseCholesky<std::complex<double>>>(
        sigma == 0.0 ? I.ZK : Complex(I.ZK - sigma * I.ZM));
  else
    I.realFactor = std::make_unique<solvers::SparseCholesky<double>>(sigma == 0.0 ? I.K : Real(I.K - sigma * I.M));
}

bool HarmonicForm::factored() const { return impl_->realFactor || impl_->complexFactor; }

void HarmonicForm::solveShifted(const Eigen::MatrixXd& x, Eigen::MatrixXd& y) const {
  if (impl_->complexForm) toReal(impl_->complexFactor->solve(toComplex(x)), y);
  else y = impl_->realFactor->solve(x);
}

double HarmonicForm::factorNonzeros() const {
  if (impl_->complexFactor) return impl_->complexFactor->factorNonzeros();
  return impl_->realFactor ? impl_->realFactor->factorNonzeros() : 0.0;
}

}  // namespace cyclone::cyclic
