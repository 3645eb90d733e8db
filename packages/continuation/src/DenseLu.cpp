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

Eigen::VectorXd DenseLu::solve(const Eigen::VectorXd& b) const {
  const int n = int(factors_.rows());
  if (b.size() != n) throw std::invalid_argument("DenseLu: the right-hand side's size differs from the matrix's");
  if (info_ != 0) return Eigen::VectorXd::Constant(n, std::numeric_limits<double>::quiet_NaN());
  Eigen::VectorXd x = b;
  int info = 0;
  Teuchos::LAPACK<int, double>().GETRS('N', n, 1, factors_.data(), std::max(n, 1), pivots_.data(), x.data(),
                                       std::max(n, 1), &info);
  if (info != 0) x.setConstant(std::numeric_limits<double>::quiet_NaN());
  return x;
}

}  // namespace cyclone::continuation
