#pragma once
// The LU factorisation (partial pivoting) of a dense square matrix by LAPACK's
// dgetrf/dgetrs through Teuchos::LAPACK: 2-3x faster than Eigen's PartialPivLU
// from n ~ 1000 on one core with OpenBLAS (docs/solvers.md), and the continuation's
// correctors factor a bordered Jacobian at every Newton iteration.
#include <Eigen/Core>
#include <vector>

namespace cyclone::continuation {

class DenseLu {
public:
  DenseLu() = default;
  explicit DenseLu(const Eigen::MatrixXd& A) { compute(A); }
  void compute(const Eigen::MatrixXd& A);
  /// A^-1 b; not finite where A is singular (an exactly zero pivot).
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const;
  /// A^-T b (the same factors).
  Eigen::VectorXd solveTransposed(const Eigen::VectorXd& b) const;

private:
  Eigen::MatrixXd factors_;
  std::vector<int> pivots_;
  int info_ = 0;
};

}  // namespace cyclone::continuation
