#include "cyclone/hbm/ModalDamping.hpp"

#include <Eigen/Eigenvalues>

#include "cyclone/core/Error.hpp"

namespace cyclone::hbm {

Eigen::MatrixXd modalDamping(const Eigen::MatrixXd& M, const Eigen::MatrixXd& K, double zeta) {
  if (!(zeta >= 0)) throw InputError("modal damping", "must be >= 0");
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> modes(K, M);
  if (modes.info() != Eigen::Success || modes.eigenvalues().minCoeff() < 0)
    throw InputError("modal damping", "needs K positive semi-definite and M positive definite");
  const Eigen::MatrixXd MPhi = M * modes.eigenvectors();
  const Eigen::VectorXd c = 2 * zeta * modes.eigenvalues().cwiseMax(0).cwiseSqrt();
  return MPhi * c.asDiagonal() * MPhi.transpose();
}

}  // namespace cyclone::hbm
