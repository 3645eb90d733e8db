// Centrifugal load rho Omega^2 r_perp: resultant against the closed form of affine
// elements and tet blocks (first moment = volume x centroid), zero resultant about an
// axis through the centroid, nodal values of the linear tet, and axis handling.
#include <gtest/gtest.h>

#include "ElementTestSupport.hpp"

using namespace cyclone::fe;
using namespace cyclone::fe::test;

namespace {

const double kRho = 4.507e-9, kOmega = 1200.0;  // t/mm^3, rad/s

Eigen::Vector3d resultant(const Eigen::VectorXd& f) {
  Eigen::Vector3d total = Eigen::Vector3d::Zero();
  for (Eigen::Index a = 0; a < f.size() / 3; ++a) total += f.segment<3>(3 * a);
  return total;
}

RotationAxis randomAxis(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  RotationAxis axis;
  axis.point = Eigen::Vector3d(u(rng), u(rng), u(rng));
  axis.direction = Eigen::Vector3d(u(rng), u(rng), 3.0);  // deliberately not unit length
  return axis;
}

class CentrifugalLoadTest : public ::testing::TestWithParam<ElementType> {};

// r_perp is affine in x, so int r_perp dV = V r_perp(centroid).
TEST_P(CentrifugalLoadTest, AffineElementResultantIsMassTimesCentroidDistance) {
  const auto t = GetParam();
  std::mt19937 rng(51);
  for (int k = 0; k < 5; ++k) {
    const Eigen::Matrix3d A = randomAffineMatrix(rng);
    const Eigen::Vector3d c(4, 1, -2);
    const ElementCoords X = affineElement(t, A, c);
    const RotationAxis axis = randomAxis(rng);
    const double V = A.determinant() * referenceVolume(t);
    const Eigen::Vector3d centroid = A * referenceCentroid(t) + c;
    const Eigen::Vector3d expected =
        kRho * kOmega * kOmega * V * distanceFromAxis(centroid, axis.point, axis.direction);
    const Eigen::VectorXd f = elementCentrifugalLoad(t, X, kRho, kOmega, axis);
    EXPECT_LT((resultant(f) - expected).norm(), 1e-13 * expected.norm());
    // Every nodal load is perpendicular to the axis.
    const Eigen::Vector3d a = axis.direction.normalized();
    for (int n = 0; n < nodeCount(t); ++n) EXPECT_NEAR(f.segment<3>(3 * n).dot(a), 0.0, 1e-13 * expected.norm());
  }
}

TEST_P(CentrifugalLoadTest, ResultantVanishesAboutAnAxisThroughTheCentroid) {
  const auto t = GetParam();
  std::mt19937 rng(52);
  const Eigen::Matrix3d A = randomAffineMatrix(rng);
  const Eigen::Vector3d c(4, 1, -2);
  const ElementCoords X = affineElement(t, A, c);
  RotationAxis axis = randomAxis(rng);
  axis.point = A * referenceCentroid(t) + c;
  const double V = A.determinant() * referenceVolume(t);
  const double scale = kRho * kOmega * kOmega * V * X.cwiseAbs().maxCoeff();
  const Eigen::VectorXd f = elementCentrifugalLoad(t, X, kRho, kOmega, axis);
  EXPECT_LT(resultant(f).norm(), 1e-13 * scale);
  EXPECT_GT(f.norm(), 1e-3 * scale);  // the nodal loads themselves are not zero
}

TEST_P(CentrifugalLoadTest, AxisDirectionLengthAndSignDoNotMatter) {
  const auto t = GetParam();
  std::mt19937 rng(53);
  const ElementCoords X = distortedElement(t, rng);
  RotationAxis axis = randomAxis(rng);
  const Eigen::VectorXd f = elementCentrifugalLoad(t, X, kRho, kOmega, axis);
  axis.direction *= -7.5;
  const Eigen::VectorXd g = elementCentrifugalLoad(t, X, kRho, kOmega, axis);
  EXPECT_LT((f - g).cwiseAbs().maxCoeff(), 1e-13 * f.cwiseAbs().maxCoeff());
}

INSTANTIATE_TEST_SUITE_P(AllTypes, CentrifugalLoadTest, ::testing::ValuesIn(kAllTypes),
                         [](const auto& info) { return nameOf(info.param); });

// Linear tet: int L_a L_b dV = V (1 + delta_ab) / 20 and r_perp = sum_b L_b r_perp(x_b), so
// f_a = rho Omega^2 V / 20 (r_perp(x_a) + sum_b r_perp(x_b)).
TEST(CentrifugalLoad, Tet4NodalLoadsMatchClosedForm) {
  std::mt19937 rng(54);
  const ElementCoords X = distortedElement(ElementType::Tet4, rng, 0.2);
  const RotationAxis axis = randomAxis(rng);
  Eigen::Matrix<double, 3, 4> r;
  for (int a = 0; a < 4; ++a) r.col(a) = distanceFromAxis(X.row(a).transpose(), axis.point, axis.direction);
  Eigen::Matrix3d edges;
  for (int j = 0; j < 3; ++j) edges.col(j) = (X.row(j + 1) - X.row(0)).transpose();
  const double V = edges.determinant() / 6.0;
  const Eigen::VectorXd f = elementCentrifugalLoad(ElementType::Tet4, X, kRho, kOmega, axis);
  for (int a = 0; a < 4; ++a) {
    const Eigen::Vector3d expected = kRho * kOmega * kOmega * V / 20.0 * (r.col(a) + r.rowwise().sum());
    EXPECT_LT((f.segment<3>(3 * a) - expected).norm(), 1e-13 * expected.norm()) << "node " << a;
  }
}

// A body of distorted straight-edged tets: int r_perp dV = sum_e V_e r_perp(centroid_e),
// and about the axis through the body's centroid the resultant vanishes.
TEST(CentrifugalLoad, TetBlockResultantMatchesFirstMomentOfVolume) {
  for (auto t : {ElementType::Tet4, ElementType::Tet10}) {
    std::mt19937 rng(55);
    const PatchMesh mesh = distortedBlock(t, rng);
    double volume = 0;
    Eigen::Vector3d moment = Eigen::Vector3d::Zero();
    for (int e = 0; e < static_cast<int>(mesh.elements.size()); ++e) {
      const ElementCoords X = mesh.coords(e);
      Eigen::Matrix3d edges;
      for (int j = 0; j < 3; ++j) edges.col(j) = (X.row(j + 1) - X.row(0)).transpose();
      const double V = edges.determinant() / 6.0;
      volume += V;
      moment += V * X.topRows(4).colwise().mean().transpose();
    }
    RotationAxis axis = randomAxis(rng);
    auto bodyResultant = [&] {
      Eigen::Vector3d total = Eigen::Vector3d::Zero();
      for (int e = 0; e < static_cast<int>(mesh.elements.size()); ++e)
        total += resultant(elementCentrifugalLoad(t, mesh.coords(e), kRho, kOmega, axis));
      return total;
    };
    // r_perp is affine, so the sum of V_e r_perp(c_e) is r_perp applied to the first moment.
    const Eigen::Vector3d a = axis.direction.normalized();
    Eigen::Vector3d integral = moment - volume * axis.point;
    integral -= integral.dot(a) * a;
    const Eigen::Vector3d expected = kRho * kOmega * kOmega * integral;
    EXPECT_LT((bodyResultant() - expected).norm(), 1e-12 * expected.norm()) << nameOf(t);

    axis.point = moment / volume;
    EXPECT_LT(bodyResultant().norm(), 1e-12 * kRho * kOmega * kOmega * volume * 3.0) << nameOf(t);
  }
}

TEST(CentrifugalLoad, ZeroAxisDirectionIsRejected) {
  std::mt19937 rng(56);
  RotationAxis axis;
  axis.direction.setZero();
  EXPECT_THROW(elementCentrifugalLoad(ElementType::Hex8, distortedElement(ElementType::Hex8, rng), kRho, kOmega, axis),
               cyclone::Error);
}

}  // namespace
