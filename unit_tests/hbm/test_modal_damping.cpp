// Modal damping (ModalDamping.hpp): every mode of (K, M) gets 2 zeta w_j, the modes found
// here by another route (the eigenvectors of M^-1 K), and a negative ratio is refused.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include "cyclone/core/Error.hpp"
#include "cyclone/hbm/ModalDamping.hpp"

using namespace cyclone;

TEST(ModalDamping, DampsEveryModeByTheRatio) {
  Eigen::Matrix3d M, K;
  M << 2.0, 0.3, 0.0, 0.3, 1.0, 0.1, 0.0, 0.1, 0.5;
  K << 14.0, -4.0, -2.0, -4.0, 4.0, 0.0, -2.0, 0.0, 2.0;
  const double zeta = 0.03;
  const Eigen::MatrixXd C = hbm::modalDamping(M, K, zeta);
  const Eigen::EigenSolver<Eigen::Matrix3d> modes(M.inverse() * K);
  for (int j = 0; j < 3; ++j) {
    const Eigen::Vector3d phi = modes.eigenvectors().col(j).real();
    const double w = std::sqrt(modes.eigenvalues()(j).real());
    // phi^T C phi / phi^T M phi = 2 zeta w for each mode, and no coupling to the others.
    EXPECT_NEAR(phi.dot(C * phi) / phi.dot(M * phi), 2 * zeta * w, 1e-12 * w);
    for (int i = 0; i < j; ++i)
      EXPECT_NEAR(modes.eigenvectors().col(i).real().dot(C * phi), 0.0, 1e-12 * C.norm() * phi.squaredNorm());
  }
  EXPECT_THROW(hbm::modalDamping(M, K, -0.01), InputError);
}
