#include "cyclone/continuation/DenseLu.hpp"

#include <Teuchos_LAPACK.hpp>
#include <limits>
#include <stdexcept>

namespace cyclone::continuation {

void DenseLu::compute(const Eigen::MatrixXd& A) {
  if (A.rows() != A.cols()) throw std::invalid_argument("DenseLu: the matrix is not square");
  factors_ = A;
  const int n = int(A.rows());
  pivots_.resize(std::size_t(n));
  Teuchos::LAPACK<int, double>().GETRF(n, n, factors_.data(), std::max(n, 1), pivots_.data(), &info_);
}

namespace {
Eigen::VectorXd solveWith(char trans, const Eigen::MatrixXd& factors, const std::vector<int>& pivots, int info0,
                          const Eigen::VectorXd& b) {
  const int n = int(factors.rows());
  if (b.size() != n) throw std::invalid_argument("DenseLu: the right-hand side's size differs from the matrix's");
  if (info0 != 0) return Eigen::VectorXd::Constant(n, std::numeric_limits<double>::quiet_NaN());
  Eigen::VectorXd x = b;
  int info = 0;
  Teuchos::LAPACK<int, double>().GETRS(trans, n, 1, factors.data(), std::max(n, 1), pivots.data(), x.data(),
                                       std::max(n, 1), &info);
  if (info != 0) x.setConstant(std::numeric_limits<double>::quiet_NaN());
  return x;
}
}  // namespace

Eigen::VectorXd DenseLu::solve(const Eigen::VectorXd& b) const { return solveWith('N', factors_, pivots_, info_, b); }

Eigen::VectorXd DenseLu::solveTransposed(const Eigen::VectorXd& b) const {
  return solveWith('T', factors_, pivots_, info_, b);
}

}  // namespace cyclone::continuation
