// Consistent mass, volume and uniform body load against closed forms: total mass of
// affinely mapped elements, the tet mass matrices integrated in barycentric
// coordinates, the box hex8 mass, and the nodal shares of a uniform body force.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <map>

#include "ElementTestSupport.hpp"

using namespace cyclone::fe;
using namespace cyclone::fe::test;

namespace {

const double kRho = 7.85e-9;

class ElementMassTest : public ::testing::TestWithParam<ElementType> {};

TEST_P(ElementMassTest, AffineElementVolumeAndTotalMassMatchClosedForm) {
  const auto t = GetParam();
  std::mt19937 rng(31);
  for (int k = 0; k < 5; ++k) {
    const Eigen::Matrix3d A = randomAffineMatrix(rng);
    const ElementCoords X = affineElement(t, A, Eigen::Vector3d(3, -4, 5));
    const double volume = A.determinant() * referenceVolume(t);
    ASSERT_GT(volume, 0);
    EXPECT_NEAR(elementVolume(t, X), volume, 1e-14 * volume);
    const Eigen::MatrixXd M = elementMass(t, X, kRho);
    EXPECT_NEAR(M.sum() / 3.0, kRho * volume, 1e-13 * kRho * volume);
  }
}

TEST_P(ElementMassTest, DistortedElementMassIsConsistentAndPositiveDefinite) {
  const auto t = GetParam();
  std::mt19937 rng(32);
  for (int k = 0; k < 5; ++k) {
    const ElementCoords X = distortedElement(t, rng);
    const Eigen::MatrixXd M = elementMass(t, X, kRho);
    const double volume = elementVolume(t, X);
    EXPECT_NEAR(M.sum() / 3.0, kRho * volume, 1e-13 * kRho * volume);
    EXPECT_EQ((M - M.transpose()).cwiseAbs().maxCoeff(), 0.0) << "not exactly symmetric";
    // Directions do not couple: M = m (x) I3.
    for (int i = 0; i < M.rows(); ++i)
      for (int j = 0; j < M.cols(); ++j) {
        if (i % 3 != j % 3) {
          ASSERT_EQ(M(i, j), 0.0);
        }
      }
    EXPECT_GT(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(M).eigenvalues().minCoeff(), 0.0);
    // Uniform body force: the nodal loads add up to b V.
    const Eigen::Vector3d b(1.0, -2.0, 0.5);
    const Eigen::VectorXd f = elementBodyLoad(t, X, b);
    Eigen::Vector3d total = Eigen::Vector3d::Zero();
    for (int a = 0; a < nodeCount(t); ++a) total += f.segment<3>(3 * a);
    EXPECT_LT((total - volume * b).norm(), 1e-13 * volume * b.norm());
  }
}

// Nodal shares of int N_a dV for an affine element, derived by hand:
//   tet4 V/4;  tet10 corners int L(2L-1) = -V/20, mid-edges int 4 Li Lj = V/5;
//   hex8 V/8;  hex20 corners -V/8, mid-edges V/6.
TEST_P(ElementMassTest, UniformBodyLoadOfAffineElementMatchesClosedForm) {
  const auto t = GetParam();
  std::mt19937 rng(33);
  const Eigen::Matrix3d A = randomAffineMatrix(rng);
  const ElementCoords X = affineElement(t, A, Eigen::Vector3d(-1, 2, 0.5));
  const double V = A.determinant() * referenceVolume(t);
  const Eigen::Vector3d b(0.0, 0.0, -9.81e-6);
  const Eigen::VectorXd f = elementBodyLoad(t, X, b);
  for (int a = 0; a < nodeCount(t); ++a) {
    const bool corner = a < (isTet(t) ? 4 : 8);
    double share = 0;
    switch (t) {
      case ElementType::Tet4: share = V / 4; break;
      case ElementType::Tet10: share = corner ? -V / 20 : V / 5; break;
      case ElementType::Hex8: share = V / 8; break;
      case ElementType::Hex20: share = corner ? -V / 8 : V / 6; break;
    }
    EXPECT_LT((f.segment<3>(3 * a) - share * b).norm(), 1e-14 * V * b.norm()) << "node " << a;
  }
}

INSTANTIATE_TEST_SUITE_P(AllTypes, ElementMassTest, ::testing::ValuesIn(kAllTypes),
                         [](const auto& info) { return nameOf(info.param); });

// Polynomials in the barycentric coordinates L0..L3 of a tet, integrated exactly with
//   int L0^a L1^b L2^c L3^d dV = 3! V a! b! c! d! / (a+b+c+d+3)!.
using Exponents = std::array<int, 4>;
using Polynomial = std::map<Exponents, double>;

Polynomial product(const Polynomial& p, const Polynomial& q) {
  Polynomial r;
  for (const auto& [a, ca] : p)
    for (const auto& [b, cb] : q) r[{a[0] + b[0], a[1] + b[1], a[2] + b[2], a[3] + b[3]}] += ca * cb;
  return r;
}

double integrate(const Polynomial& p, double V) {
  double s = 0;
  for (const auto& [e, c] : p) {
    const int order = e[0] + e[1] + e[2] + e[3];
    s += c * 6.0 * V * std::tgamma(e[0] + 1) * std::tgamma(e[1] + 1) * std::tgamma(e[2] + 1) *
         std::tgamma(e[3] + 1) / std::tgamma(order + 4);
  }
  return s;
}

Exponents unit(int i) {
  Exponents e = {0, 0, 0, 0};
  ++e[i];
  return e;
}

// tet4: L_a.  tet10: corners L(2L-1), mid-edges 4 Li Lj (edges 01 12 20 03 13 23).
Polynomial tetShape(ElementType t, int a) {
  static const int edges[6][2] = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};
  if (t == ElementType::Tet4) return {{unit(a), 1.0}};
  if (a < 4) {
    Exponents square = {0, 0, 0, 0};
    square[a] = 2;
    return {{square, 2.0}, {unit(a), -1.0}};
  }
  Exponents e = unit(edges[a - 4][0]);
  ++e[edges[a - 4][1]];
  return {{e, 4.0}};
}

TEST(ElementMass, TetMassMatricesMatchBarycentricIntegration) {
  std::mt19937 rng(34);
  for (auto t : {ElementType::Tet4, ElementType::Tet10}) {
    const Eigen::Matrix3d A = randomAffineMatrix(rng);
    const ElementCoords X = affineElement(t, A, Eigen::Vector3d(1, 1, 1));
    const double V = A.determinant() / 6.0;
    const Eigen::MatrixXd M = elementMass(t, X, kRho);
    double largest = M.cwiseAbs().maxCoeff();
    for (int a = 0; a < nodeCount(t); ++a)
      for (int b = 0; b < nodeCount(t); ++b) {
        const double expected = kRho * integrate(product(tetShape(t, a), tetShape(t, b)), V);
        for (int d = 0; d < 3; ++d)
          EXPECT_NEAR(M(3 * a + d, 3 * b + d), expected, 1e-13 * largest) << nameOf(t) << " M(" << a << "," << b << ")";
      }
  }
}

// Box hx x hy x hz: the 1-D linear mass (h/6)[2 1; 1 2] in each direction, so
// M_ab = rho V / 216 * 2^(number of coordinates in which nodes a and b agree).
TEST(ElementMass, BoxHex8MassMatchesTensorProductClosedForm) {
  const Eigen::Vector3d h(3.0, 0.5, 1.25);
  const ElementCoords X = affineElement(ElementType::Hex8, (0.5 * h).asDiagonal(), Eigen::Vector3d(10, 0, -2));
  const double V = h.prod();
  const Eigen::MatrixXd M = elementMass(ElementType::Hex8, X, kRho);
  // Corner signs in Exodus order.
  const int s[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1}, {-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}};
  for (int a = 0; a < 8; ++a)
    for (int b = 0; b < 8; ++b) {
      int agree = 0;
      for (int d = 0; d < 3; ++d) agree += s[a][d] == s[b][d];
      const double expected = kRho * V / 216.0 * std::pow(2.0, agree);
      for (int d = 0; d < 3; ++d) EXPECT_NEAR(M(3 * a + d, 3 * b + d), expected, 1e-14 * kRho * V);
    }
}

}  // namespace
