// Reference elements: shape functions against their defining properties (Kronecker delta
// at the nodes, partition of unity, polynomial reproduction), gradients against finite
// differences, and Gauss rules against closed-form monomial integrals.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "cyclone/mesh/ReferenceElement.hpp"

using namespace cyclone::mesh;

namespace {

const ElementType kAllTypes[] = {ElementType::Tet4, ElementType::Tet10, ElementType::Hex8, ElementType::Hex20};

std::string nameOf(ElementType t) {
  switch (t) {
    case ElementType::Tet4: return "Tet4";
    case ElementType::Tet10: return "Tet10";
    case ElementType::Hex8: return "Hex8";
    case ElementType::Hex20: return "Hex20";
  }
  return "?";
}

bool isTet(ElementType t) { return t == ElementType::Tet4 || t == ElementType::Tet10; }
bool isQuadratic(ElementType t) { return t == ElementType::Tet10 || t == ElementType::Hex20; }
int nodeCount(ElementType t) { return t == ElementType::Tet4 ? 4 : t == ElementType::Tet10 ? 10 : t == ElementType::Hex8 ? 8 : 20; }

// Node coordinates written out from the Exodus II node-ordering figures.
Eigen::Matrix<double, Eigen::Dynamic, 3> expectedNodes(ElementType t) {
  Eigen::Matrix<double, Eigen::Dynamic, 3> X(nodeCount(t), 3);
  switch (t) {
    case ElementType::Tet4: X << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1; break;
    case ElementType::Tet10:
      X << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1,  //
          .5, 0, 0, .5, .5, 0, 0, .5, 0, 0, 0, .5, .5, 0, .5, 0, .5, .5;
      break;
    case ElementType::Hex8: X << -1, -1, -1, 1, -1, -1, 1, 1, -1, -1, 1, -1, -1, -1, 1, 1, -1, 1, 1, 1, 1, -1, 1, 1; break;
    case ElementType::Hex20:
      X << -1, -1, -1, 1, -1, -1, 1, 1, -1, -1, 1, -1, -1, -1, 1, 1, -1, 1, 1, 1, 1, -1, 1, 1,  // corners
          0, -1, -1, 1, 0, -1, 0, 1, -1, -1, 0, -1,                                          // 01 12 23 30
          0, -1, 1, 1, 0, 1, 0, 1, 1, -1, 0, 1,                                              // 45 56 67 74
          -1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0;                                            // 04 15 26 37
      break;
  }
  return X;
}

// Places every mid-edge node at the midpoint of its edge's corners.
void straightenMidEdges(ElementType t, Eigen::Matrix<double, Eigen::Dynamic, 3>& X) {
  static const int tet10[6][2] = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};
  static const int hex20[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                                   {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
  if (t == ElementType::Tet10)
    for (int e = 0; e < 6; ++e) X.row(4 + e) = 0.5 * (X.row(tet10[e][0]) + X.row(tet10[e][1]));
  if (t == ElementType::Hex20)
    for (int e = 0; e < 12; ++e) X.row(8 + e) = 0.5 * (X.row(hex20[e][0]) + X.row(hex20[e][1]));
}

// Uniform random point in the reference domain.
Eigen::Vector3d randomReferencePoint(ElementType t, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(isTet(t) ? 0.0 : -1.0, 1.0);
  while (true) {
    Eigen::Vector3d x(u(rng), u(rng), u(rng));
    if (!isTet(t) || x.sum() <= 1.0) return x;
  }
}

class ReferenceElementTest : public ::testing::TestWithParam<ElementType> {};

TEST_P(ReferenceElementTest, NodesAreInExodusOrder) {
  const auto t = GetParam();
  const auto X = referenceNodes(t);
  ASSERT_EQ(X.rows(), nodeCount(t));
  EXPECT_EQ(X, expectedNodes(t));
}

TEST_P(ReferenceElementTest, ShapeFunctionsAreKroneckerDeltaAtNodes) {
  const auto t = GetParam();
  const auto X = expectedNodes(t);
  ShapeValues N;
  ShapeGradients dN;
  for (int j = 0; j < X.rows(); ++j) {
    evaluateShape(t, X.row(j).transpose(), N, dN);
    ASSERT_EQ(N.size(), X.rows());
    for (int i = 0; i < X.rows(); ++i) EXPECT_NEAR(N[i], i == j ? 1.0 : 0.0, 1e-15) << "N_" << i << " at node " << j;
  }
}

TEST_P(ReferenceElementTest, PartitionOfUnityAndGradientsSumToZero) {
  const auto t = GetParam();
  std::mt19937 rng(11);
  ShapeValues N;
  ShapeGradients dN;
  for (int k = 0; k < 50; ++k) {
    evaluateShape(t, randomReferencePoint(t, rng), N, dN);
    EXPECT_NEAR(N.sum(), 1.0, 1e-14);
    EXPECT_LT(dN.colwise().sum().cwiseAbs().maxCoeff(), 1e-13);
  }
}

// Isoparametric completeness: sum_a N_a f(x_a) = f(x) for every f in the element's space.
TEST_P(ReferenceElementTest, ReproducesCompletePolynomials) {
  const auto t = GetParam();
  const auto X = expectedNodes(t);
  std::mt19937 rng(12);
  ShapeValues N;
  ShapeGradients dN;
  auto linear = [](const Eigen::Vector3d& x) { return 0.3 - 1.1 * x[0] + 2.2 * x[1] + 0.7 * x[2]; };
  auto quadratic = [&](const Eigen::Vector3d& x) {
    return linear(x) + 0.5 * x[0] * x[0] - 1.5 * x[1] * x[1] + 0.25 * x[2] * x[2] + 1.3 * x[0] * x[1] - 0.6 * x[1] * x[2] +
           0.9 * x[0] * x[2];
  };
  for (int k = 0; k < 20; ++k) {
    const Eigen::Vector3d x = randomReferencePoint(t, rng);
    evaluateShape(t, x, N, dN);
    double lin = 0, quad = 0;
    for (int a = 0; a < X.rows(); ++a) {
      lin += N[a] * linear(X.row(a).transpose());
      quad += N[a] * quadratic(X.row(a).transpose());
    }
    EXPECT_NEAR(lin, linear(x), 1e-13);
    if (isQuadratic(t)) {
      EXPECT_NEAR(quad, quadratic(x), 1e-13);
    }
    // The identity map: sum_a x_a grad N_a = I.
    const Eigen::Matrix3d J = X.transpose() * dN;
    EXPECT_LT((J - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff(), 1e-13);
  }
}

TEST_P(ReferenceElementTest, GradientsMatchCentralFiniteDifferences) {
  const auto t = GetParam();
  std::mt19937 rng(13);
  ShapeValues N, Np, Nm;
  ShapeGradients dN, scratch;
  const double h = 1e-6;
  for (int k = 0; k < 20; ++k) {
    const Eigen::Vector3d x = randomReferencePoint(t, rng);
    evaluateShape(t, x, N, dN);
    for (int j = 0; j < 3; ++j) {
      const Eigen::Vector3d step = h * Eigen::Vector3d::Unit(j);
      evaluateShape(t, x + step, Np, scratch);
      evaluateShape(t, x - step, Nm, scratch);
      const Eigen::VectorXd fd = (Np - Nm) / (2 * h);
      EXPECT_LT((fd - dN.col(j)).cwiseAbs().maxCoeff(), 1e-8) << "d/dxi_" << j;
    }
  }
}

// Closed forms: tet  int x^a y^b z^c = a! b! c! / (a+b+c+3)!;
//               cube int_{-1}^{1} x^a = 2/(a+1) for even a, 0 for odd a.
double exactMonomialIntegral(ElementType t, int a, int b, int c) {
  if (isTet(t)) return std::tgamma(a + 1) * std::tgamma(b + 1) * std::tgamma(c + 1) / std::tgamma(a + b + c + 4);
  auto oneD = [](int p) { return p % 2 ? 0.0 : 2.0 / (p + 1); };
  return oneD(a) * oneD(b) * oneD(c);
}

double ruleMonomialIntegral(const QuadratureRule& r, int a, int b, int c) {
  double s = 0;
  for (std::size_t q = 0; q < r.points.size(); ++q)
    s += r.weights[q] * std::pow(r.points[q][0], a) * std::pow(r.points[q][1], b) * std::pow(r.points[q][2], c);
  return s;
}

// Monomials a rule of degree d must integrate exactly: total degree <= d on the tet,
// each exponent <= d on the cube (tensor-product Gauss rules).
bool inRuleSpace(ElementType t, int degree, int a, int b, int c) {
  return isTet(t) ? a + b + c <= degree : std::max({a, b, c}) <= degree;
}

void checkRule(ElementType t, const QuadratureRule& r, int expectedDegree, std::size_t expectedPoints) {
  SCOPED_TRACE(r.name);
  EXPECT_EQ(r.degree, expectedDegree);
  ASSERT_EQ(r.points.size(), expectedPoints);
  ASSERT_EQ(r.weights.size(), expectedPoints);
  for (std::size_t q = 0; q < r.points.size(); ++q) {
    EXPECT_GT(r.weights[q], 0.0);
    const auto& x = r.points[q];
    if (isTet(t)) {
      EXPECT_TRUE(x.minCoeff() > 0 && x.sum() < 1) << "point " << q << " outside the tet";
    } else {
      EXPECT_LT(x.cwiseAbs().maxCoeff(), 1.0) << "point " << q << " outside the cube";
    }
  }
  const int d = r.degree;
  bool sharp = false;  // some monomial of degree d+1 is not integrated exactly
  for (int a = 0; a <= d + 1; ++a)
    for (int b = 0; b <= d + 1; ++b)
      for (int c = 0; c <= d + 1; ++c) {
        const double exact = exactMonomialIntegral(t, a, b, c), rule = ruleMonomialIntegral(r, a, b, c);
        if (inRuleSpace(t, d, a, b, c)) {
          EXPECT_NEAR(rule, exact, 1e-15 + 1e-14 * std::abs(exact)) << "x^" << a << " y^" << b << " z^" << c;
        } else if (a + b + c == d + 1 && std::abs(rule - exact) > 1e-12) {
          sharp = true;
        }
      }
  EXPECT_TRUE(sharp) << "the rule is exact beyond its declared degree " << d;
}

TEST_P(ReferenceElementTest, StiffnessRuleIntegratesMonomialsExactly) {
  const auto t = GetParam();
  switch (t) {
    case ElementType::Tet4: checkRule(t, stiffnessRule(t), 1, 1); break;
    case ElementType::Tet10: checkRule(t, stiffnessRule(t), 2, 4); break;
    case ElementType::Hex8: checkRule(t, stiffnessRule(t), 3, 8); break;
    case ElementType::Hex20: checkRule(t, stiffnessRule(t), 5, 27); break;
  }
}

TEST_P(ReferenceElementTest, MassRuleIntegratesMonomialsExactly) {
  const auto t = GetParam();
  switch (t) {
    case ElementType::Tet4: checkRule(t, massRule(t), 2, 4); break;
    case ElementType::Tet10: checkRule(t, massRule(t), 5, 14); break;
    case ElementType::Hex8: checkRule(t, massRule(t), 3, 8); break;
    case ElementType::Hex20: checkRule(t, massRule(t), 5, 27); break;
  }
}

TEST_P(ReferenceElementTest, MinJacobianDeterminantOfAffineMapIsItsDeterminant) {
  const auto t = GetParam();
  Eigen::Matrix3d A;
  A << 2.0, 0.3, -0.1, 0.2, 1.5, 0.4, -0.3, 0.1, 0.8;
  const Eigen::Vector3d c(5, -2, 1);
  const auto ref = expectedNodes(t);
  Eigen::Matrix<double, Eigen::Dynamic, 3> X(ref.rows(), 3);
  for (int a = 0; a < ref.rows(); ++a) X.row(a) = (A * ref.row(a).transpose() + c).transpose();
  EXPECT_NEAR(minJacobianDeterminant(t, X), A.determinant(), 1e-13);
  // A reflection inverts the element.
  X.col(2) *= -1;
  EXPECT_NEAR(minJacobianDeterminant(t, X), -A.determinant(), 1e-13);
}

TEST_P(ReferenceElementTest, MinJacobianDeterminantSeesALocallyInvertedNode) {
  const auto t = GetParam();
  auto X = expectedNodes(t);
  // Push corner 0 through the opposite side of the element: inverted at that corner.
  X.row(0) = isTet(t) ? Eigen::RowVector3d(0.6, 0.6, 0.6) : Eigen::RowVector3d(1.5, 1.5, 1.5);
  straightenMidEdges(t, X);  // mid-edge nodes follow their corners
  EXPECT_LT(minJacobianDeterminant(t, X), 0.0);
}

INSTANTIATE_TEST_SUITE_P(AllTypes, ReferenceElementTest, ::testing::ValuesIn(kAllTypes),
                         [](const auto& info) { return nameOf(info.param); });

}  // namespace
