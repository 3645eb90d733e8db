// The Total Lagrangian St Venant-Kirchhoff element: small-displacement limit,
// objectivity under a large rigid rotation, a closed-form uniaxial stretch, and
// its analytic tangent against finite differences of the internal force.
#include <gtest/gtest.h>

#include <cmath>

#include "cyclone/fe/ElementKernels.hpp"
#include "cyclone/mesh/ReferenceElement.hpp"

using namespace cyclone;

namespace {
const mesh::ElementType kTypes[] = {mesh::ElementType::Tet4, mesh::ElementType::Tet10, mesh::ElementType::Hex8,
                                    mesh::ElementType::Hex20};
const fe::IsotropicElastic kSteel{"steel", 2.1e5, 0.3, 7.85e-9};

fe::ElementCoords distorted(mesh::ElementType type) {
  Eigen::Matrix3d F;
  F << 1.2, 0.1, -0.05, 0.0, 0.9, 0.2, 0.1, -0.1, 1.1;
  const auto ref = mesh::referenceNodes(type);
  fe::ElementCoords X(ref.rows(), 3);
  for (int a = 0; a < ref.rows(); ++a) X.row(a) = (F * ref.row(a).transpose()).transpose();
  return X;
}
}  // namespace

TEST(TotalLagrangian, SmallDisplacementLimitIsTheLinearElement) {
  for (auto type : kTypes) {
    const auto X = distorted(type);
    // Strains ~1e-6: the quadratic part is ~1e-6 relative, well above the round-off of
    // forming E = (F^T F - I) / 2, which grows as eps / strain.
    const Eigen::VectorXd u = 1e-6 * Eigen::VectorXd::Random(3 * X.rows());
    const auto tl = fe::elementTotalLagrangian(type, X, kSteel, Eigen::VectorXd::Zero(3 * X.rows()), true);
    const Eigen::MatrixXd K = fe::elementStiffness(type, X, kSteel);
    EXPECT_LT((tl.tangent - K).norm(), 1e-12 * K.norm()) << mesh::exodusName(type);
    const auto small = fe::elementTotalLagrangian(type, X, kSteel, u, false);
    EXPECT_LT((small.internalForce - K * u).norm(), 1e-5 * (K * u).norm()) << mesh::exodusName(type);
  }
}

TEST(TotalLagrangian, LargeRigidRotationIsStressFree) {
  const Eigen::Matrix3d R = Eigen::AngleAxisd(1.1, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  for (auto type : kTypes) {
    const auto X = distorted(type);
    Eigen::VectorXd u(3 * X.rows());
    for (int a = 0; a < X.rows(); ++a) u.segment<3>(3 * a) = (R - Eigen::Matrix3d::Identity()) * X.row(a).transpose();
    const auto tl = fe::elementTotalLagrangian(type, X, kSteel, u, false);
    EXPECT_LT(tl.internalForce.norm(), 1e-9 * kSteel.E) << mesh::exodusName(type);
    EXPECT_LT(tl.secondPK.norm(), 1e-9 * kSteel.E) << mesh::exodusName(type);
  }
}

TEST(TotalLagrangian, UniaxialStretchClosedForm) {
  // x -> (1 + s) x, y, z fixed: E11 = s + s^2/2, S = D E, Cauchy sigma11 = (1+s) S11.
  const double s = 0.05;
  const auto D = kSteel.elasticity();
  for (auto type : kTypes) {
    const auto X = distorted(type);
    Eigen::VectorXd u = Eigen::VectorXd::Zero(3 * X.rows());
    for (int a = 0; a < X.rows(); ++a) u(3 * a) = s * X(a, 0);
    const auto tl = fe::elementTotalLagrangian(type, X, kSteel, u, false);
    const double E11 = s + 0.5 * s * s;
    for (int q = 0; q < tl.secondPK.rows(); ++q) {
      EXPECT_NEAR(tl.secondPK(q, 0), D(0, 0) * E11, 1e-9 * kSteel.E);
      EXPECT_NEAR(tl.secondPK(q, 1), D(1, 0) * E11, 1e-9 * kSteel.E);
      EXPECT_NEAR(tl.cauchy(q, 0), (1 + s) * D(0, 0) * E11, 1e-9 * kSteel.E);
      EXPECT_NEAR(tl.cauchy(q, 1), D(1, 0) * E11 / (1 + s), 1e-9 * kSteel.E);
    }
  }
}

TEST(TotalLagrangian, TangentMatchesFiniteDifferences) {
  for (auto type : kTypes) {
    const auto X = distorted(type);
    const int m = 3 * int(X.rows());
    const Eigen::VectorXd u = 0.05 * Eigen::VectorXd::Random(m);  // finite strains
    const auto tl = fe::elementTotalLagrangian(type, X, kSteel, u, true);
    const double h = 1e-6;
    Eigen::MatrixXd fd(m, m);
    for (int j = 0; j < m; ++j) {
      Eigen::VectorXd up = u, um = u;
      up(j) += h, um(j) -= h;
      fd.col(j) = (fe::elementTotalLagrangian(type, X, kSteel, up, false).internalForce -
                   fe::elementTotalLagrangian(type, X, kSteel, um, false).internalForce) / (2 * h);
    }
    EXPECT_LT((fd - tl.tangent).norm() / tl.tangent.norm(), 1e-7) << mesh::exodusName(type);
  }
}
