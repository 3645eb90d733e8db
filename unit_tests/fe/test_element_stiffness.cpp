// Element stiffness: rigid-body null space of distorted elements, symmetry, and the
// constant-strain tet against its closed form V B^T D B.
#include <gtest/gtest.h>

#include "ElementTestSupport.hpp"

using namespace cyclone::fe;
using namespace cyclone::fe::test;

namespace {

IsotropicElastic steel() {
  IsotropicElastic m;
  m.name = "steel";
  m.E = 2.1e5;
  m.nu = 0.3;
  m.rho = 7.85e-9;
  return m;
}

// The six rigid-body motions (3 translations, 3 infinitesimal rotations) at the nodes.
Eigen::MatrixXd rigidBodyModes(const ElementCoords& X) {
  Eigen::MatrixXd R = Eigen::MatrixXd::Zero(3 * X.rows(), 6);
  for (int a = 0; a < X.rows(); ++a) {
    const Eigen::Vector3d x = X.row(a).transpose();
    for (int d = 0; d < 3; ++d) {
      R(3 * a + d, d) = 1.0;
      R.block<3, 1>(3 * a, 3 + d) = Eigen::Vector3d::Unit(d).cross(x);
    }
  }
  return R;
}

class ElementStiffnessTest : public ::testing::TestWithParam<ElementType> {};

TEST_P(ElementStiffnessTest, DistortedElementHasExactlySixRigidBodyModes) {
  const auto t = GetParam();
  std::mt19937 rng(21);
  for (int k = 0; k < 5; ++k) {
    const ElementCoords X = distortedElement(t, rng);
    const Eigen::MatrixXd K = elementStiffness(t, X, steel());
    ASSERT_EQ(K.rows(), 3 * nodeCount(t));
    EXPECT_EQ((K - K.transpose()).cwiseAbs().maxCoeff(), 0.0) << "not exactly symmetric";
    const Eigen::VectorXd lambda = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(K).eigenvalues();
    const double largest = lambda.maxCoeff();
    for (int i = 0; i < 6; ++i) EXPECT_LT(std::abs(lambda[i]), 1e-11 * largest) << "eigenvalue " << i;
    EXPECT_GT(lambda[6], 1e-4 * largest) << "spurious zero-energy mode";
    // The null space is exactly the rigid-body motions.
    const Eigen::MatrixXd residual = K * rigidBodyModes(X);
    EXPECT_LT(residual.cwiseAbs().maxCoeff(), 1e-10 * largest * X.cwiseAbs().maxCoeff());
  }
}

INSTANTIATE_TEST_SUITE_P(AllTypes, ElementStiffnessTest, ::testing::ValuesIn(kAllTypes),
                         [](const auto& info) { return nameOf(info.param); });

// Constant-strain tet: N_i = c_i + g_i . x with [c_i; g_i] the columns of C^-1,
// C = [1 x_j y_j z_j] (rows j), V = det C / 6, K = V B^T D B.
TEST(ElementStiffness, Tet4MatchesConstantStrainClosedForm) {
  std::mt19937 rng(22);
  for (int k = 0; k < 5; ++k) {
    const ElementCoords X = distortedElement(ElementType::Tet4, rng, 0.2);
    Eigen::Matrix4d C;
    for (int j = 0; j < 4; ++j) C.row(j) << 1.0, X(j, 0), X(j, 1), X(j, 2);
    const Eigen::Matrix4d coefficients = C.inverse();
    const double volume = C.determinant() / 6.0;
    ASSERT_GT(volume, 0);
    Eigen::Matrix<double, 6, 12> B = Eigen::Matrix<double, 6, 12>::Zero();
    for (int i = 0; i < 4; ++i) {
      const double gx = coefficients(1, i), gy = coefficients(2, i), gz = coefficients(3, i);
      B.block<6, 3>(0, 3 * i) << gx, 0, 0, 0, gy, 0, 0, 0, gz, 0, gz, gy, gz, 0, gx, gy, gx, 0;
    }
    const auto m = steel();
    const Eigen::Matrix<double, 12, 12> expected = volume * B.transpose() * lameElasticity(m.E, m.nu) * B;
    const Eigen::MatrixXd K = elementStiffness(ElementType::Tet4, X, m);
    EXPECT_LT((K - expected).cwiseAbs().maxCoeff(), 1e-12 * expected.cwiseAbs().maxCoeff());
  }
}

// Stiffness is E * length: doubling every coordinate doubles K, and translation leaves it.
TEST(ElementStiffness, ScalesWithElementSizeAndIgnoresTranslation) {
  std::mt19937 rng(23);
  for (auto t : kAllTypes) {
    const ElementCoords X = distortedElement(t, rng);
    const Eigen::MatrixXd K = elementStiffness(t, X, steel());
    const ElementCoords moved = (2.0 * X).rowwise() + Eigen::RowVector3d(100, -50, 7);
    const Eigen::MatrixXd K2 = elementStiffness(t, moved, steel());
    EXPECT_LT((K2 - 2.0 * K).cwiseAbs().maxCoeff(), 1e-11 * K.cwiseAbs().maxCoeff()) << nameOf(t);
  }
}

}  // namespace
