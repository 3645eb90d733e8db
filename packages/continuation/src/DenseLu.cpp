#include "cyclone/continuation/DenseLu.hpp"

#include <Teuchos_LAPACK.hpp>
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

void DenseLu::factorHeldMatrix(Precision precision) {
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
  const int n = int(matrix_.rows());
  const Teuchos::LAPACK<int, float> lapack;
  Eigen::VectorXf work(n);
  // d = A^-1 r (or A^-T r) from the single factors of A / alpha, r scaled to order one.
  const auto singleSolve = [&](const Eigen::VectorXd& r, Eigen::VectorXd& d) {
    const double s = r.cwiseAbs().maxCoeff();
    if (!(s > 0)) {
      d.setZero(n);
      return std::isfinite(s);
    }
    work = (r / s).cast<float>();
    int info = 0;
    lapack.GETRS(trans, n, 1, singleFactors_.data(), std::max(n, 1), singlePivots_.data(), work.data(),
                 std::max(n, 1), &info);
    d = work.cast<double>() * (s / alpha_);
    return info == 0 && d.allFinite();
  };
  if (!singleSolve(b, x)) return false;
  const double tolerance = normInf_ * std::numeric_limits<double>::epsilon() * std::sqrt(double(n));
  Eigen::VectorXd r, d;
  for (int step = 0; step <= maxRefinementSteps; ++step) {
    r = trans == 'N' ? Eigen::VectorXd(b - matrix_ * x) : Eigen::VectorXd(b - matrix_.transpose() * x);
    if (!r.allFinite()) return false;
    if (r.cwiseAbs().maxCoeff() <= x.cwiseAbs().maxCoeff() * tolerance) return true;
    if (step == maxRefinementSteps || !singleSolve(r, d)) return false;
    x += d;
    ++refinementSteps_;
  }
  return false;
}

Eigen::VectorXd DenseLu::solveWith(char trans, const Eigen::VectorXd& b) const {
  const int n = int(mixed_ ? matrix_.rows() : factors_.rows());
  if (b.size() != n) throw std::invalid_argument("DenseLu: the right-hand side's size differs from the matrix's");
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
