#include "cyclone/fe/ElementKernels.hpp"

#include <array>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "cyclone/mesh/ReferenceElement.hpp"

namespace cyclone::fe {

namespace {

std::string geometryMessage(int point, double detJ) {
  std::ostringstream s;
  s.precision(6);
  s << "inverted or degenerate element: det J = " << detJ << " at integration point " << point;
  return s.str();
}

// Shape values and reference gradients at the points of one rule, computed once per
// (element type, rule): the kernels then do no shape-function work per element.
struct ShapeTable {
  std::vector<double> weights;
  std::vector<mesh::ShapeValues> N;
  std::vector<mesh::ShapeGradients> dN;
  int numPoints() const { return static_cast<int>(weights.size()); }
};

ShapeTable tabulate(ElementType type, const mesh::QuadratureRule& rule) {
  ShapeTable t;
  t.weights = rule.weights;
  t.N.resize(rule.points.size());
  t.dN.resize(rule.points.size());
  for (std::size_t q = 0; q < rule.points.size(); ++q) mesh::evaluateShape(type, rule.points[q], t.N[q], t.dN[q]);
  return t;
}

enum class Rule { Stiffness, Mass };

// The rule of the mass-like terms.
Rule massLike(MassQuadrature quadrature) {
  return quadrature == MassQuadrature::Exact ? Rule::Mass : Rule::Stiffness;
}

const ShapeTable& shapeTable(ElementType type, Rule rule) {
  constexpr std::array<ElementType, 4> types = {ElementType::Tet4, ElementType::Tet10, ElementType::Hex8,
                                                ElementType::Hex20};
  static const std::array<ShapeTable, 8> tables = [&] {
    std::array<ShapeTable, 8> all;
    for (int i = 0; i < 4; ++i) {
      all[2 * i] = tabulate(types[i], mesh::stiffnessRule(types[i]));
      all[2 * i + 1] = tabulate(types[i], mesh::massRule(types[i]));
    }
    return all;
  }();
  return tables[2 * static_cast<int>(type) + (rule == Rule::Mass ? 1 : 0)];
}

int checkedNodeCount(ElementType type, const ElementCoords& X) {
  const int n = mesh::nodesPerElement(type);
  if (X.rows() != n)
    throw Error("element kernel: " + std::to_string(X.rows()) + " coordinate rows for a " +
                mesh::exodusName(type) + " element of " + std::to_string(n) + " nodes");
  return n;
}

// A node-by-node scalar matrix s (n x n) as the element matrix s (x) I_3 on
// node-major DOFs: the same coupling in every direction (mass, geometric stiffness).
Eigen::MatrixXd perDirection(const Eigen::MatrixXd& s) {
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(3 * s.rows(), 3 * s.cols());
  for (Eigen::Index a = 0; a < s.rows(); ++a)
    for (Eigen::Index b = 0; b < s.cols(); ++b)
      for (int d = 0; d < 3; ++d) K(3 * a + d, 3 * b + d) = s(a, b);
  return K;
}

// det J below this fraction of (bounding-box diagonal)^3 is round-off of a flat element:
// treated as degenerate like det J <= 0, since its stiffness would be meaningless.
constexpr double kDegenerateRelativeDetJ = 1e-14;

double degenerateDetJ(const ElementCoords& X) {
  const double h = (X.colwise().maxCoeff() - X.colwise().minCoeff()).norm();
  return kDegenerateRelativeDetJ * h * h * h;
}

// Jacobian J(i,j) = dx_i/dxi_j at point q; throws for an inverted or degenerate element.
Eigen::Matrix3d jacobian(const ShapeTable& t, int q, const ElementCoords& X, double floor, double& detJ) {
  const Eigen::Matrix3d J = X.transpose().lazyProduct(t.dN[q]);
  detJ = J.determinant();
  if (!(detJ > floor)) throw InvalidElementGeometry(q, detJ);
  return J;
}

// Strain-displacement matrix, Voigt xx yy zz yz xz xy with engineering shear, from the
// physical gradients G (n x 3); B must be 6 x 3n and zero outside the filled pattern.
void fillB(const ElementCoords& G, Eigen::Matrix<double, 6, Eigen::Dynamic>& B) {
  for (Eigen::Index a = 0; a < G.rows(); ++a) {
    const double gx = G(a, 0), gy = G(a, 1), gz = G(a, 2);
    const Eigen::Index c = 3 * a;
    B(0, c) = gx;
    B(1, c + 1) = gy;
    B(2, c + 2) = gz;
    B(3, c + 1) = gz, B(3, c + 2) = gy;
    B(4, c) = gz, B(4, c + 2) = gx;
    B(5, c) = gy, B(5, c + 1) = gx;
  }
}

// B at rule point q; returns w * det J.
double strainDisplacement(const ShapeTable& t, int q, const ElementCoords& X, double floor, ElementCoords& G,
                          Eigen::Matrix<double, 6, Eigen::Dynamic>& B) {
  double detJ;
  const Eigen::Matrix3d J = jacobian(t, q, X, floor, detJ);
  const Eigen::Matrix3d Jinv = J.inverse();
  G.noalias() = t.dN[q].lazyProduct(Jinv);  // dN/dx = dN/dxi * dxi/dx
  fillB(G, B);
  return t.weights[q] * detJ;
}

Eigen::Vector3d unitAxis(const RotationAxis& axis) {
  const double norm = axis.direction.norm();
  if (!(norm > 0) || !std::isfinite(norm)) throw Error("centrifugal load: the rotation axis direction is zero");
  return axis.direction / norm;
}

}  // namespace

InvalidElementGeometry::InvalidElementGeometry(int point, double detJ)
    : Error(geometryMessage(point, detJ)), point(point), detJ(detJ) {}

Eigen::MatrixXd elementStiffness(ElementType type, const ElementCoords& X, const IsotropicElastic& mat) {
  const int n = checkedNodeCount(type, X);
  const auto& t = shapeTable(type, Rule::Stiffness);
  const double floor = degenerateDetJ(X);
  const Eigen::Matrix<double, 6, 6> D = mat.elasticity();
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(3 * n, 3 * n);
  Eigen::Matrix<double, 6, Eigen::Dynamic> B = Eigen::Matrix<double, 6, Eigen::Dynamic>::Zero(6, 3 * n), DB(6, 3 * n);
  ElementCoords G(n, 3);
  for (int q = 0; q < t.numPoints(); ++q) {
    const double wdetJ = strainDisplacement(t, q, X, floor, G, B);
    DB.noalias() = wdetJ * D * B;
    K.noalias() += B.transpose() * DB;
  }
  // Exactly symmetric, whatever the product's summation order did.
  K = 0.5 * (K + K.transpose()).eval();
  return K;
}

Eigen::MatrixXd elementMass(ElementType type, const ElementCoords& X, double rho, MassQuadrature quadrature) {
  const int n = checkedNodeCount(type, X);
  const auto& t = shapeTable(type, massLike(quadrature));
  const double floor = degenerateDetJ(X);
  Eigen::MatrixXd m = Eigen::MatrixXd::Zero(n, n);  // scalar mass, the same for each direction
  for (int q = 0; q < t.numPoints(); ++q) {
    double detJ;
    jacobian(t, q, X, floor, detJ);
    m.selfadjointView<Eigen::Lower>().rankUpdate(t.N[q], rho * t.weights[q] * detJ);
  }
  m = m.selfadjointView<Eigen::Lower>();  // exactly symmetric
  return perDirection(m);
}

Eigen::VectorXd elementCentrifugalLoad(ElementType type, const ElementCoords& X, double rho, double omega,
                                       const RotationAxis& axis, MassQuadrature quadrature) {
  const int n = checkedNodeCount(type, X);
  const auto& t = shapeTable(type, massLike(quadrature));
  const double floor = degenerateDetJ(X);
  const Eigen::Vector3d a = unitAxis(axis);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(3 * n);
  for (int q = 0; q < t.numPoints(); ++q) {
    double detJ;
    jacobian(t, q, X, floor, detJ);
    const Eigen::Vector3d x = X.transpose().lazyProduct(t.N[q]);
    Eigen::Vector3d r = x - axis.point;
    r -= r.dot(a) * a;  // distance vector from the axis
    const Eigen::Vector3d density = (rho * omega * omega * t.weights[q] * detJ) * r;
    for (int b = 0; b < n; ++b) f.segment<3>(3 * b) += t.N[q][b] * density;
  }
  return f;
}

Eigen::VectorXd elementBodyLoad(ElementType type, const ElementCoords& X, const Eigen::Vector3d& b) {
  const int n = checkedNodeCount(type, X);
  const auto& t = shapeTable(type, Rule::Mass);
  const double floor = degenerateDetJ(X);
  Eigen::VectorXd nodal = Eigen::VectorXd::Zero(n);  // int N_a dV
  for (int q = 0; q < t.numPoints(); ++q) {
    double detJ;
    jacobian(t, q, X, floor, detJ);
    nodal += (t.weights[q] * detJ) * t.N[q];
  }
  Eigen::VectorXd f(3 * n);
  for (int a = 0; a < n; ++a) f.segment<3>(3 * a) = nodal[a] * b;
  return f;
}

double elementVolume(ElementType type, const ElementCoords& X) {
  checkedNodeCount(type, X);
  const auto& t = shapeTable(type, Rule::Mass);  // the rule of the mass matrix: total mass = rho * volume
  const double floor = degenerateDetJ(X);
  double volume = 0;
  for (int q = 0; q < t.numPoints(); ++q) {
    double detJ;
    jacobian(t, q, X, floor, detJ);
    volume += t.weights[q] * detJ;
  }
  return volume;
}

Eigen::Matrix<double, Eigen::Dynamic, 6> elementStresses(ElementType type, const ElementCoords& X,
                                                         const IsotropicElastic& mat, const Eigen::VectorXd& ue) {
  const int n = checkedNodeCount(type, X);
  if (ue.size() != 3 * n)
    throw Error("elementStresses: displacement vector of size " + std::to_string(ue.size()) + " for a " +
                mesh::exodusName(type) + " element of " + std::to_string(n) + " nodes");
  const auto& t = shapeTable(type, Rule::Stiffness);
  const double floor = degenerateDetJ(X);
  const Eigen::Matrix<double, 6, 6> D = mat.elasticity();
  Eigen::Matrix<double, 6, Eigen::Dynamic> B = Eigen::Matrix<double, 6, Eigen::Dynamic>::Zero(6, 3 * n);
  ElementCoords G(n, 3);
  Eigen::Matrix<double, Eigen::Dynamic, 6> S(t.numPoints(), 6);
  for (int q = 0; q < t.numPoints(); ++q) {
    strainDisplacement(t, q, X, floor, G, B);
    const Eigen::Matrix<double, 6, 1> strain = B * ue;
    S.row(q) = (D * strain).transpose();
  }
  return S;
}

Eigen::MatrixXd elementGeometricStiffness(ElementType type, const ElementCoords& X,
                                          const Eigen::Matrix<double, Eigen::Dynamic, 6>& stress) {
  const int n = checkedNodeCount(type, X);
  const auto& t = shapeTable(type, Rule::Stiffness);
  if (stress.rows() != t.numPoints())
    throw Error("elementGeometricStiffness: " + std::to_string(stress.rows()) + " stress rows for a rule of " +
                std::to_string(t.numPoints()) + " points");
  const double floor = degenerateDetJ(X);
  Eigen::MatrixXd g = Eigen::MatrixXd::Zero(n, n);  // scalar part, the same for each direction
  for (int q = 0; q < t.numPoints(); ++q) {
    double detJ;
    const Eigen::Matrix3d J = jacobian(t, q, X, floor, detJ);
    const ElementCoords G = t.dN[q] * J.inverse();
    const auto& s = stress.row(q);
    Eigen::Matrix3d S;
    S << s(0), s(5), s(4), s(5), s(1), s(3), s(4), s(3), s(2);
    g.noalias() += (t.weights[q] * detJ) * (G * S * G.transpose());
  }
  g = 0.5 * (g + g.transpose()).eval();
  return perDirection(g);
}

Eigen::MatrixXd elementSpinSoftening(ElementType type, const ElementCoords& X, double rho, double omega,
                                     const RotationAxis& axis, MassQuadrature quadrature) {
  const int n = checkedNodeCount(type, X);
  const Eigen::Vector3d a = unitAxis(axis);
  const Eigen::Matrix3d P = Eigen::Matrix3d::Identity() - a * a.transpose();
  const Eigen::MatrixXd M = elementMass(type, X, rho * omega * omega, quadrature);  // blocks m_ab I_3
  Eigen::MatrixXd K(3 * n, 3 * n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) K.block<3, 3>(3 * i, 3 * j) = M(3 * i, 3 * j) * P;
  return K;
}

TotalLagrangianElement elementTotalLagrangian(ElementType type, const ElementCoords& X, const IsotropicElastic& mat,
                                              const Eigen::VectorXd& ue, bool wantTangent) {
  const int n = checkedNodeCount(type, X);
  if (ue.size() != 3 * n) throw Error("elementTotalLagrangian: displacement vector of the wrong size");
  const auto& t = shapeTable(type, Rule::Stiffness);
  const double floor = degenerateDetJ(X);
  const Eigen::Matrix<double, 6, 6> D = mat.elasticity();
  TotalLagrangianElement out;
  out.internalForce = Eigen::VectorXd::Zero(3 * n);
  if (wantTangent) out.tangent = Eigen::MatrixXd::Zero(3 * n, 3 * n);
  out.secondPK.resize(t.numPoints(), 6);
  out.cauchy.resize(t.numPoints(), 6);
  Eigen::Matrix<double, 6, Eigen::Dynamic> B(6, 3 * n);
  Eigen::Matrix<double, Eigen::Dynamic, 3> U(n, 3);
  for (int a = 0; a < n; ++a) U.row(a) = ue.segment<3>(3 * a).transpose();
  for (int q = 0; q < t.numPoints(); ++q) {
    double detJ;
    const Eigen::Matrix3d J = jacobian(t, q, X, floor, detJ);
    const ElementCoords G = t.dN[q] * J.inverse();  // dN/dX in the reference configuration
    const Eigen::Matrix3d F = Eigen::Matrix3d::Identity() + U.transpose() * G;
    const Eigen::Matrix3d E = 0.5 * (F.transpose() * F - Eigen::Matrix3d::Identity());
    Eigen::Matrix<double, 6, 1> e;
    e << E(0, 0), E(1, 1), E(2, 2), 2 * E(1, 2), 2 * E(0, 2), 2 * E(0, 1);
    const Eigen::Matrix<double, 6, 1> S = D * e;
    out.secondPK.row(q) = S.transpose();
    Eigen::Matrix3d St;
    St << S(0), S(5), S(4), S(5), S(1), S(3), S(4), S(3), S(2);
    const Eigen::Matrix3d sigma = F * St * F.transpose() / F.determinant();
    out.cauchy.row(q) << sigma(0, 0), sigma(1, 1), sigma(2, 2), sigma(1, 2), sigma(0, 2), sigma(0, 1);
    // delta E = B delta u: row ij of node a, component k: (F_ki G_aj + F_kj G_ai) / (1 or 2).
    for (int a = 0; a < n; ++a)
      for (int k = 0; k < 3; ++k) {
        const int c = 3 * a + k;
        B(0, c) = F(k, 0) * G(a, 0);
        B(1, c) = F(k, 1) * G(a, 1);
        B(2, c) = F(k, 2) * G(a, 2);
        B(3, c) = F(k, 1) * G(a, 2) + F(k, 2) * G(a, 1);
        B(4, c) = F(k, 0) * G(a, 2) + F(k, 2) * G(a, 0);
        B(5, c) = F(k, 0) * G(a, 1) + F(k, 1) * G(a, 0);
      }
    const double w = t.weights[q] * detJ;
    out.internalForce.noalias() += w * (B.transpose() * S);
    if (wantTangent) {
      out.tangent.noalias() += w * (B.transpose() * D * B);
      out.tangent += perDirection(w * (G * St * G.transpose()));
    }
  }
  if (wantTangent) out.tangent = 0.5 * (out.tangent + out.tangent.transpose()).eval();
  return out;
}

double vonMises(const Eigen::Matrix<double, 6, 1>& s) {
  const double dxy = s[0] - s[1], dyz = s[1] - s[2], dzx = s[2] - s[0];
  return std::sqrt(0.5 * (dxy * dxy + dyz * dyz + dzx * dzx) + 3.0 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]));
}

}  // namespace cyclone::fe
