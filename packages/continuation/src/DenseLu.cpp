#include "cyclone/continuation/DenseLu.hpp"

#include <Teuchos_LAPACK.hpp>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace cyclone::continuation {

namespace {
// dsgesv's limit on the refinement steps before it factors in double.
constexpr int maxRefinementSteps = 30;
}  // namespace

void DenseLu::compute(const Eigen::MatrixXd& A, Precision precision) {
  if (A.rows() != A.cols()) throw std::invalid_argument("DenseLu: the matrix is not square");
  matrix_ = A;
  factorHeldMatrix(precision);
}

void DenseLu::computeTaking(Eigen::MatrixXd& A, Precision precision) {
  if (A.rows() != A.cols()) throw std::invalid_argument("DenseLu: the matrix is not square");
  matrix_.swap(A);
  factorHeldMatrix(precision);
}

bool DenseLu::reuseFactorsFor(Eigen::MatrixXd& A) {
  if (A.rows() != A.cols()) throw std::invalid_argument("DenseLu: the matrix is not square");
  const bool haveFactors = (mixed_ && !doubleFactored_) ? singleFactors_.rows() == A.rows()
                                                        : factors_.rows() == A.rows() && info_ == 0;
  // Kept only while a stale solve costs well under a factorisation: the matrix gets
  // one to three solves (Newton's step, its polish, the tangent).
  if (!haveFactors || A.rows() == 0 || lastStaleIterations_ > staleIterationBudget(int(A.rows()))) return false;
  matrix_.swap(A);
  normInf_ = matrix_.cwiseAbs().rowwise().sum().maxCoeff();
  stale_ = true;
  return true;
}

void DenseLu::factorHeldMatrix(Precision precision) {
  precision_ = precision;
  stale_ = false;
  lastStaleIterations_ = 0;
  const int n = int(matrix_.rows());
  mixed_ = precision == Precision::Mixed || (precision == Precision::Auto && n >= mixedPrecisionFrom);
  doubleFactored_ = false;
  refinementSteps_ = 0;
  info_ = 0;
  if (!mixed_) {
    factors_.swap(matrix_);
    matrix_.resize(0, 0);
    singleFactors_.resize(0, 0);
    factorInDouble();
    return;
  }
  // ||A||_inf and the largest entry in one pass over A (column-major).
  Eigen::VectorXd rowSums = Eigen::VectorXd::Zero(n);
  double largest = 0;
  for (int j = 0; j < n; ++j) {
    const auto column = matrix_.col(j).cwiseAbs();
    rowSums += column;
    largest = std::max(largest, column.maxCoeff());
  }
  normInf_ = n > 0 ? rowSums.maxCoeff() : 0.0;
  // Scaled by the largest entry so that single precision's range holds the matrix
  // whatever its units (a stiffness in N/m and a parameter column side by side).
  alpha_ = largest > 0 && std::isfinite(largest) ? largest : 1.0;
  singleFactors_ = (matrix_ * (1.0 / alpha_)).cast<float>();
  singlePivots_.resize(std::size_t(n));
  int info = 0;
  if (std::isfinite(normInf_) && singleFactors_.allFinite())
    Teuchos::LAPACK<int, float>().GETRF(n, n, singleFactors_.data(), std::max(n, 1), singlePivots_.data(), &info);
  else
    info = -1;
  if (info != 0) {  // singular in single precision, or not representable: double decides
    singleFactors_.resize(0, 0);
    factorInDouble();
  }
}

// The double LU into factors_ (mixed: of a copy of A, which the refinement keeps).
void DenseLu::factorInDouble() const {
  if (mixed_) factors_ = matrix_;
  const int n = int(factors_.rows());
  pivots_.resize(std::size_t(n));
  Teuchos::LAPACK<int, double>().GETRF(n, n, factors_.data(), std::max(n, 1), pivots_.data(), &info_);
  doubleFactored_ = true;
}

bool DenseLu::refinedSolve(char trans, const Eigen::VectorXd& b, Eigen::VectorXd& x) const {
  if (!applyFactors(trans, b, x)) return false;
  const double tolerance = residualTolerance();
  Eigen::VectorXd r, d;
  for (int step = 0; step <= maxRefinementSteps; ++step) {
    r = trans == 'N' ? Eigen::VectorXd(b - matrix_ * x) : Eigen::VectorXd(b - matrix_.transpose() * x);
    if (!r.allFinite()) return false;
    if (r.cwiseAbs().maxCoeff() <= x.cwiseAbs().maxCoeff() * tolerance) return true;
    if (step == maxRefinementSteps || !applyFactors(trans, r, d)) return false;
    x += d;
    ++refinementSteps_;
  }
  return false;
}

double DenseLu::residualTolerance() const {
  return normInf_ * std::numeric_limits<double>::epsilon() * std::sqrt(double(matrix_.rows()));
}

// d = M^-1 r (or M^-T r) with the factors held: the single ones (scaled), or the double.
bool DenseLu::applyFactors(char trans, const Eigen::VectorXd& r, Eigen::VectorXd& d) const {
  const int n = int(r.size());
  if (mixed_ && !doubleFactored_) {
    const double s = r.cwiseAbs().maxCoeff();
    if (!(s > 0)) {
      d.setZero(n);
      return std::isfinite(s);
    }
    Eigen::VectorXf work = (r / s).cast<float>();
    int info = 0;
    Teuchos::LAPACK<int, float>().GETRS(trans, n, 1, singleFactors_.data(), std::max(n, 1), singlePivots_.data(),
                                        work.data(), std::max(n, 1), &info);
    d = work.cast<double>() * (s / alpha_);
    return info == 0 && d.allFinite();
  }
  d = r;
  int info = 0;
  Teuchos::LAPACK<int, double>().GETRS(trans, n, 1, factors_.data(), std::max(n, 1), pivots_.data(), d.data(),
                                       std::max(n, 1), &info);
  return info == 0 && d.allFinite();
}

// GMRES on A M^-1 y = b, x = M^-1 y (M the factors held, of an older matrix), from
// x0 = M^-1 b, with classical Gram-Schmidt applied twice (orthogonal to rounding, and
// matrix-vector products rather than a loop of dot products); its estimate of ||r||_2
// stops the iteration, the true residual decides, with the refinement's test. The
// preconditioned directions M^-1 v are kept (flexible GMRES): a single-precision solve
// is not the same linear map on a combination of vectors as on each, and x formed by
// one more such solve would carry its rounding (1e-7 of x).
bool DenseLu::krylovSolve(char trans, const Eigen::VectorXd& b, Eigen::VectorXd& x) const {
  const int n = int(matrix_.rows()), m = maxKrylovIterations;
  const auto product = [&](const Eigen::VectorXd& v) -> Eigen::VectorXd {
    return trans == 'N' ? Eigen::VectorXd(matrix_ * v) : Eigen::VectorXd(matrix_.transpose() * v);
  };
  if (!applyFactors(trans, b, x)) return false;
  const double tolerance = residualTolerance();
  Eigen::VectorXd r = b - product(x);
  const auto converged = [&] { return r.allFinite() && r.cwiseAbs().maxCoeff() <= x.cwiseAbs().maxCoeff() * tolerance; };
  if (converged()) return true;
  const double beta = r.norm();
  if (!(beta > 0) || !std::isfinite(beta)) return false;
  Eigen::MatrixXd V(n, m + 1), Z(n, m), H = Eigen::MatrixXd::Zero(m + 1, m);
  Eigen::VectorXd g = Eigen::VectorXd::Zero(m + 1), cs(m), sn(m), z, w, h;
  V.col(0) = r / beta;
  g(0) = beta;
  int k = 0;
  // The estimate aims below the test's ||r||_inf bound (||r||_inf <= ||r||_2).
  const double target = 0.5 * x.cwiseAbs().maxCoeff() * tolerance;
  while (k < m) {
    if (!applyFactors(trans, V.col(k), z)) return false;
    Z.col(k) = z;
    w = product(z);
    h = V.leftCols(k + 1).transpose() * w;
    w -= V.leftCols(k + 1) * h;
    const Eigen::VectorXd h2 = V.leftCols(k + 1).transpose() * w;
    w -= V.leftCols(k + 1) * h2;
    h += h2;
    H.col(k).head(k + 1) = h;
    H(k + 1, k) = w.norm();
    ++krylovIterations_;
    if (!std::isfinite(H(k + 1, k))) return false;
    const bool breakdown = !(H(k + 1, k) > 0);  // the Krylov space holds the solution
    if (!breakdown) V.col(k + 1) = w / H(k + 1, k);
    for (int i = 0; i < k; ++i) {  // the earlier rotations on the new column
      const double a = H(i, k), c = H(i + 1, k);
      H(i, k) = cs(i) * a + sn(i) * c;
      H(i + 1, k) = -sn(i) * a + cs(i) * c;
    }
    const double a = H(k, k), c = H(k + 1, k), rho = std::hypot(a, c);
    if (!(rho > 0)) return false;
    cs(k) = a / rho, sn(k) = c / rho;
    H(k, k) = rho, H(k + 1, k) = 0;
    g(k + 1) = -sn(k) * g(k);
    g(k) = cs(k) * g(k);
    ++k;
    if (std::abs(g(k)) <= target || breakdown) break;
  }
  const Eigen::VectorXd y =
      H.topLeftCorner(k, k).triangularView<Eigen::Upper>().solve(g.head(k));
  x += Z.leftCols(k) * y;
  r = b - product(x);
  return converged();
}

Eigen::VectorXd DenseLu::solveWith(char trans, const Eigen::VectorXd& b) const {
  const int n = int(mixed_ || stale_ ? matrix_.rows() : factors_.rows());
  if (b.size() != n) throw std::invalid_argument("DenseLu: the right-hand side's size differs from the matrix's");
  if (stale_) {
    Eigen::VectorXd x;
    const long before = krylovIterations_;
    const bool solved = krylovSolve(trans, b, x);
    lastStaleIterations_ = int(krylovIterations_ - before);
    if (solved) return x;
    // The kept factors did not serve: the matrix's own (the solve below).
    ++staleRefactorizations_;
    const_cast<DenseLu*>(this)->factorHeldMatrix(precision_);  // const: the answer is the same matrix's
  }
  if (mixed_ && !doubleFactored_) {
    Eigen::VectorXd x;
    if (refinedSolve(trans, b, x)) return x;
    factorInDouble();
  }
  if (info_ != 0) return Eigen::VectorXd::Constant(n, std::numeric_limits<double>::quiet_NaN());
  Eigen::VectorXd x = b;
  int info = 0;
  Teuchos::LAPACK<int, double>().GETRS(trans, n, 1, factors_.data(), std::max(n, 1), pivots_.data(), x.data(),
                                       std::max(n, 1), &info);
  if (info != 0) x.setConstant(std::numeric_limits<double>::quiet_NaN());
  return x;
}

Eigen::VectorXd DenseLu::solve(const Eigen::VectorXd& b) const { return solveWith('N', b); }

Eigen::VectorXd DenseLu::solveTransposed(const Eigen::VectorXd& b) const { return solveWith('T', b); }

}  // namespace cyclone::continuation
