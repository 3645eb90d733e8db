#include "cyclone/mesh/ReferenceElement.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>

#include "cyclone/core/Error.hpp"

namespace cyclone::mesh {

namespace {

// Mid-edge nodes of the quadratic elements, as pairs of corners (Exodus order).
constexpr int kTet10Edges[6][2] = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};
constexpr int kHex20Edges[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                                    {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
// Hex corners on [-1,1]^3, Exodus order: bottom face counter-clockwise, then top.
constexpr double kHexCorners[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                      {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};

// Barycentric coordinates L0..L3 of a tet and their (constant) xi-gradients.
std::array<double, 4> barycentric(const Eigen::Vector3d& xi) {
  return {1.0 - xi[0] - xi[1] - xi[2], xi[0], xi[1], xi[2]};
}
const double kBarycentricGradient[4][3] = {{-1, -1, -1}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};

void tet4Shape(const Eigen::Vector3d& xi, ShapeValues& N, ShapeGradients& dN) {
  const auto L = barycentric(xi);
  for (int a = 0; a < 4; ++a) {
    N[a] = L[a];
    for (int j = 0; j < 3; ++j) dN(a, j) = kBarycentricGradient[a][j];
  }
}

void tet10Shape(const Eigen::Vector3d& xi, ShapeValues& N, ShapeGradients& dN) {
  const auto L = barycentric(xi);
  const auto& G = kBarycentricGradient;
  for (int a = 0; a < 4; ++a) {  // corners: L(2L-1)
    N[a] = L[a] * (2.0 * L[a] - 1.0);
    for (int j = 0; j < 3; ++j) dN(a, j) = (4.0 * L[a] - 1.0) * G[a][j];
  }
  for (int e = 0; e < 6; ++e) {  // mid-edges: 4 Li Lj
    const int i = kTet10Edges[e][0], k = kTet10Edges[e][1];
    N[4 + e] = 4.0 * L[i] * L[k];
    for (int j = 0; j < 3; ++j) dN(4 + e, j) = 4.0 * (G[i][j] * L[k] + L[i] * G[k][j]);
  }
}

void hex8Shape(const Eigen::Vector3d& xi, ShapeValues& N, ShapeGradients& dN) {
  for (int a = 0; a < 8; ++a) {
    const double* s = kHexCorners[a];
    const double f[3] = {1 + s[0] * xi[0], 1 + s[1] * xi[1], 1 + s[2] * xi[2]};
    N[a] = 0.125 * f[0] * f[1] * f[2];
    dN(a, 0) = 0.125 * s[0] * f[1] * f[2];
    dN(a, 1) = 0.125 * f[0] * s[1] * f[2];
    dN(a, 2) = 0.125 * f[0] * f[1] * s[2];
  }
}

// 20-node serendipity brick (e.g. Zienkiewicz & Taylor, The Finite Element Method, vol. 1, ch. 8).
void hex20Shape(const Eigen::Vector3d& xi, ShapeValues& N, ShapeGradients& dN) {
  for (int a = 0; a < 8; ++a) {  // corners: 1/8 prod(1 + s x) (s.x - 2)
    const double* s = kHexCorners[a];
    const double f[3] = {1 + s[0] * xi[0], 1 + s[1] * xi[1], 1 + s[2] * xi[2]};
    const double sx = s[0] * xi[0] + s[1] * xi[1] + s[2] * xi[2];
    N[a] = 0.125 * f[0] * f[1] * f[2] * (sx - 2.0);
    for (int j = 0; j < 3; ++j) {
      const double others = f[(j + 1) % 3] * f[(j + 2) % 3];
      dN(a, j) = 0.125 * s[j] * others * (sx - 2.0 + f[j]);
    }
  }
  for (int e = 0; e < 12; ++e) {  // mid-edges: 1/4 (1 - x_k^2) prod_{d != k} (1 + s_d x_d)
    const double* p = kHexCorners[kHex20Edges[e][0]];
    const double* q = kHexCorners[kHex20Edges[e][1]];
    double s[3];
    int k = 0;  // the coordinate along the edge
    for (int d = 0; d < 3; ++d) {
      s[d] = 0.5 * (p[d] + q[d]);
      if (s[d] == 0.0) k = d;
    }
    const int d1 = (k + 1) % 3, d2 = (k + 2) % 3;
    const double fk = 1 - xi[k] * xi[k], f1 = 1 + s[d1] * xi[d1], f2 = 1 + s[d2] * xi[d2];
    const int a = 8 + e;
    N[a] = 0.25 * fk * f1 * f2;
    dN(a, k) = -0.5 * xi[k] * f1 * f2;
    dN(a, d1) = 0.25 * fk * s[d1] * f2;
    dN(a, d2) = 0.25 * fk * f1 * s[d2];
  }
}

QuadratureRule centroidTetRule() {
  QuadratureRule r;
  r.points = {Eigen::Vector3d(0.25, 0.25, 0.25)};
  r.weights = {1.0 / 6.0};
  r.degree = 1;
  r.name = "tet 1-point centroid";
  return r;
}

// Appends the 4 points with barycentric coordinates (1-3a, a, a, a) and permutations.
void addTetOrbit31(QuadratureRule& r, double a, double w) {
  const double b = 1.0 - 3.0 * a;
  for (int i = 0; i < 4; ++i) {
    std::array<double, 4> L = {a, a, a, a};
    L[i] = b;
    r.points.emplace_back(L[1], L[2], L[3]);
    r.weights.push_back(w);
  }
}

// Appends the 6 points with barycentric coordinates (b, b, a, a), b = 1/2 - a, and permutations.
void addTetOrbit22(QuadratureRule& r, double a, double w) {
  const double b = 0.5 - a;
  for (const auto& edge : kTet10Edges) {
    std::array<double, 4> L = {a, a, a, a};
    L[edge[0]] = L[edge[1]] = b;
    r.points.emplace_back(L[1], L[2], L[3]);
    r.weights.push_back(w);
  }
}

// Degree-2 4-point rule, a = (5 - sqrt 5)/20: P. C. Hammer, O. J. Marlowe, A. H. Stroud,
// "Numerical integration over simplexes and cones", Math. Tables Aids Comput. 10 (1956).
QuadratureRule fourPointTetRule() {
  QuadratureRule r;
  addTetOrbit31(r, (5.0 - std::sqrt(5.0)) / 20.0, 1.0 / 24.0);
  r.degree = 2;
  r.name = "tet 4-point degree 2";
  return r;
}

// Degree-5 14-point rule with positive weights: N. J. Walkington, "Quadrature on simplices
// of arbitrary dimension", CMU tech. report 00-CNA-023 (2000). The parameters are roots of
// the moment equations, re-solved to 25 digits (mpmath) and checked against every monomial
// of degree <= 5 in the unit tests. Weights are for the reference volume 1/6.
QuadratureRule fourteenPointTetRule() {
  QuadratureRule r;
  addTetOrbit31(r, 0.3108859192633006097973457, 0.01878132095300264179986428);
  addTetOrbit31(r, 0.09273525031089122640232391, 0.01224884051939365825728503);
  addTetOrbit22(r, 0.04550370412564964949188053, 0.007091003462846911073011571);
  r.degree = 5;
  r.name = "tet 14-point degree 5 (Walkington)";
  return r;
}

// Tensor-product Gauss-Legendre rule with n = 2 or 3 points per direction on [-1,1]^3.
QuadratureRule gaussHexRule(int n) {
  std::vector<double> x, w;
  if (n == 2) {
    x = {-1.0 / std::sqrt(3.0), 1.0 / std::sqrt(3.0)};
    w = {1.0, 1.0};
  } else {
    x = {-std::sqrt(0.6), 0.0, std::sqrt(0.6)};
    w = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
  }
  QuadratureRule r;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        r.points.emplace_back(x[i], x[j], x[k]);
        r.weights.push_back(w[i] * w[j] * w[k]);
      }
  r.degree = 2 * n - 1;
  r.name = n == 2 ? "hex Gauss 2x2x2" : "hex Gauss 3x3x3";
  return r;
}

}  // namespace

void evaluateShape(ElementType type, const Eigen::Vector3d& xi, ShapeValues& N, ShapeGradients& dN) {
  const int n = nodesPerElement(type);
  N.resize(n);  // no-ops when already sized: callers reuse N and dN inside Gauss loops
  dN.resize(n, 3);
  switch (type) {
    case ElementType::Tet4: tet4Shape(xi, N, dN); break;
    case ElementType::Tet10: tet10Shape(xi, N, dN); break;
    case ElementType::Hex8: hex8Shape(xi, N, dN); break;
    case ElementType::Hex20: hex20Shape(xi, N, dN); break;
  }
}

Eigen::Matrix<double, Eigen::Dynamic, 3> referenceNodes(ElementType type) {
  Eigen::Matrix<double, Eigen::Dynamic, 3> X(nodesPerElement(type), 3);
  const bool isTet = type == ElementType::Tet4 || type == ElementType::Tet10;
  const int corners = isTet ? 4 : 8;
  for (int a = 0; a < corners; ++a)
    for (int j = 0; j < 3; ++j) X(a, j) = isTet ? (a == j + 1 ? 1.0 : 0.0) : kHexCorners[a][j];
  if (type == ElementType::Tet10)
    for (int e = 0; e < 6; ++e) X.row(4 + e) = 0.5 * (X.row(kTet10Edges[e][0]) + X.row(kTet10Edges[e][1]));
  if (type == ElementType::Hex20)
    for (int e = 0; e < 12; ++e) X.row(8 + e) = 0.5 * (X.row(kHex20Edges[e][0]) + X.row(kHex20Edges[e][1]));
  return X;
}

const QuadratureRule& stiffnessRule(ElementType type) {
  static const QuadratureRule tet1 = centroidTetRule(), tet4 = fourPointTetRule();
  static const QuadratureRule hex2 = gaussHexRule(2), hex3 = gaussHexRule(3);
  switch (type) {
    case ElementType::Tet4: return tet1;
    case ElementType::Tet10: return tet4;
    case ElementType::Hex8: return hex2;
    case ElementType::Hex20: return hex3;
  }
  throw Error("stiffnessRule: unknown element type " + std::to_string(static_cast<int>(type)));
}

const QuadratureRule& massRule(ElementType type) {
  static const QuadratureRule tet4 = fourPointTetRule(), tet14 = fourteenPointTetRule();
  static const QuadratureRule hex2 = gaussHexRule(2), hex3 = gaussHexRule(3);
  switch (type) {
    case ElementType::Tet4: return tet4;
    case ElementType::Tet10: return tet14;
    case ElementType::Hex8: return hex2;
    case ElementType::Hex20: return hex3;
  }
  throw Error("massRule: unknown element type " + std::to_string(static_cast<int>(type)));
}

double minJacobianDeterminant(ElementType type, const Eigen::Matrix<double, Eigen::Dynamic, 3>& coords) {
  const int n = nodesPerElement(type);
  if (coords.rows() != n)
    throw Error("minJacobianDeterminant: " + std::to_string(coords.rows()) + " node rows for an element of " +
                std::to_string(n) + " nodes");
  ShapeValues N(n);
  ShapeGradients dN(n, 3);
  double smallest = std::numeric_limits<double>::infinity();
  auto visit = [&](const Eigen::Vector3d& xi) {
    evaluateShape(type, xi, N, dN);
    const Eigen::Matrix3d J = coords.transpose().lazyProduct(dN);  // J(i,j) = dx_i / dxi_j
    smallest = std::min(smallest, J.determinant());
  };
  for (const auto& xi : stiffnessRule(type).points) visit(xi);
  for (const auto& xi : massRule(type).points) visit(xi);
  const auto nodes = referenceNodes(type);
  for (int a = 0; a < n; ++a) visit(nodes.row(a).transpose());
  return smallest;
}

}  // namespace cyclone::mesh
