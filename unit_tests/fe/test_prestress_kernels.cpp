// Geometric stiffness and spin softening against closed-form energies on
// affinely mapped elements (integrands constant, so every rule is exact):
//   linear field u = A x, constant stress S:  u^T K_sigma u = V tr(A S A^T)
//   rigid translation t:                      u^T K_Omega u = rho Omega^2 V |P t|^2
#include <gtest/gtest.h>

#include <cmath>

#include "cyclone/fe/ElementKernels.hpp"
#include "cyclone/mesh/ReferenceElement.hpp"

using namespace cyclone;

namespace {

fe::ElementCoords affineElement(mesh::ElementType type, const Eigen::Matrix3d& F, const Eigen::Vector3d& c) {
  const auto ref = mesh::referenceNodes(type);
  fe::ElementCoords X(ref.rows(), 3);
  for (int a = 0; a < ref.rows(); ++a) X.row(a) = (F * ref.row(a).transpose() + c).transpose();
  return X;
}

double referenceVolume(mesh::ElementType type) {
  return (type == mesh::ElementType::Tet4 || type == mesh::ElementType::Tet10) ? 1.0 / 6.0 : 8.0;
}

}  // namespace

TEST(PrestressKernels, GeometricStiffnessEnergyOfLinearField) {
  Eigen::Matrix3d F;
  F << 1.3, 0.2, -0.1, 0.1, 0.9, 0.3, -0.2, 0.1, 1.1;
  Eigen::Matrix3d A;
  A << 0.3, -0.2, 0.5, 0.1, 0.7, -0.4, -0.6, 0.2, 0.25;
  Eigen::Matrix3d S;
  S << 120, 15, -8, 15, -40, 22, -8, 22, 60;
  for (auto type : {mesh::ElementType::Tet4, mesh::ElementType::Tet10, mesh::ElementType::Hex8,
                    mesh::ElementType::Hex20}) {
    const auto X = affineElement(type, F, Eigen::Vector3d(2, -1, 0.5));
    const int n = int(X.rows());
    const int points = int(mesh::stiffnessRule(type).points.size());
    Eigen::Matrix<double, Eigen::Dynamic, 6> stress(points, 6);
    for (int q = 0; q < points; ++q) stress.row(q) << S(0, 0), S(1, 1), S(2, 2), S(1, 2), S(0, 2), S(0, 1);
    const Eigen::MatrixXd Kg = fe::elementGeometricStiffness(type, X, stress);
    Eigen::VectorXd u(3 * n);
    for (int a = 0; a < n; ++a) u.segment<3>(3 * a) = A * X.row(a).transpose();
    const double V = F.determinant() * referenceVolume(type);
    const double exact = V * (A * S * A.transpose()).trace();
    EXPECT_NEAR(u.dot(Kg * u) / exact, 1.0, 1e-12) << mesh::exodusName(type);
    // A rigid translation has no gradient: no geometric stiffness energy.
    Eigen::VectorXd t(3 * n);
    for (int a = 0; a < n; ++a) t.segment<3>(3 * a) = Eigen::Vector3d(1, -2, 0.5);
    EXPECT_LT((Kg * t).norm(), 1e-10 * Kg.norm());
  }
}

TEST(PrestressKernels, SpinSofteningEnergyOfTranslation) {
  Eigen::Matrix3d F;
  F << 0.8, 0.1, 0.0, -0.2, 1.2, 0.1, 0.0, 0.3, 0.9;
  const double rho = 7.85e-9, omega = 1200.0;
  mesh::RotationAxis axis;
  axis.direction = Eigen::Vector3d(1, 2, 2);  // |a| = 3, normalised by the kernel
  const Eigen::Vector3d a = axis.direction.normalized();
  const Eigen::Vector3d t(0.4, -1.0, 2.0);
  for (auto type : {mesh::ElementType::Tet4, mesh::ElementType::Tet10, mesh::ElementType::Hex8,
                    mesh::ElementType::Hex20}) {
    const auto X = affineElement(type, F, Eigen::Vector3d::Zero());
    const int n = int(X.rows());
    const Eigen::MatrixXd Ks = fe::elementSpinSoftening(type, X, rho, omega, axis);
    Eigen::VectorXd u(3 * n);
    for (int b = 0; b < n; ++b) u.segment<3>(3 * b) = t;
    const double V = F.determinant() * referenceVolume(type);
    const Eigen::Vector3d Pt = t - t.dot(a) * a;
    EXPECT_NEAR(u.dot(Ks * u) / (rho * omega * omega * V * Pt.squaredNorm()), 1.0, 1e-12) << mesh::exodusName(type);
    // Motion along the axis is not softened.
    for (int b = 0; b < n; ++b) u.segment<3>(3 * b) = a;
    EXPECT_LT((Ks * u).norm(), 1e-12 * Ks.norm());
  }
}
