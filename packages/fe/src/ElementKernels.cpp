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

// Node-by-node scalar matrices (n x n: mass, geometric stiffness) and the strain operator.
using ScalarMatrix =
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::ColMajor, kMaxElementNodes, kMaxElementNodes>;
using StrainMatrix = Eigen::Matrix<double, 6, Eigen::Dynamic, Eigen::ColMajor, 6, kMaxElementDofs>;

// K += factor s (x) I_3 on node-major DOFs: the same coupling in every direction.
void addPerDirection(const ScalarMatrix& s, double factor, ElementMatrix& K) {
  for (Eigen::Index a = 0; a < s.rows(); ++a)
    for (Eigen::Index b = 0; b < s.cols(); ++b)
      for (int d = 0; d < 3; ++d) K(3 * a + d, 3 * b + d) += factor * s(a, b);
}

// A = (A + A^T) / 2 in place: exactly symmetric, whatever a product's summation order did.
template <class Matrix>
void symmetrize(Matrix& A) {
  for (Eigen::Index j = 0; j < A.cols(); ++j)
    for (Eigen::Index i = j + 1; i < A.rows(); ++i) A(i, j) = A(j, i) = 0.5 * (A(i, j) + A(j, i));
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
void fillB(const ElementCoords& G, StrainMatrix& B) {
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
                          StrainMatrix& B) {
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

ElementMatrix elementStiffness(ElementType type, const ElementCoords& X, const IsotropicElastic& mat) {
  const int n = checkedNodeCount(type, X);
  const auto& t = shapeTable(type, Rule::Stiffness);
  const double floor = degenerateDetJ(X);
  const Eigen::Matrix<double, 6, 6> D = mat.elasticity();
  ElementMatrix K = ElementMatrix::Zero(3 * n, 3 * n);
  StrainMatrix B = StrainMatrix::Zero(6, 3 * n), DB(6, 3 * n);
  ElementCoords G(n, 3);
  for (int q = 0; q < t.numPoints(); ++q) {
    const double wdetJ = strainDisplacement(t, q, X, floor, G, B);
    DB.noalias() = wdetJ * D * B;
    K.noalias() += B.transpose() * DB;
  }
  symmetrize(K);
  return K;
}

namespace {

// The scalar mass int N N^T dV (n x n) by `rule`'s points.
void scalarMass(const ShapeTable& t, const ElementCoords& X, double floor, ScalarMatrix& m) {
  m.setZero(X.rows(), X.rows());
  for (int q = 0; q < t.numPoints(); ++q) {
    double detJ;
    jacobian(t, q, X, floor, detJ);
    m.selfadjointView<Eigen::Lower>().rankUpdate(t.N[q], t.weights[q] * detJ);
  }
  for (Eigen::Index j = 0; j < m.cols(); ++j)
    for (Eigen::Index i = j + 1; i < m.rows(); ++i) m(j, i) = m(i, j);  // exactly symmetric
}

}  // namespace

ElementMatrix elementMass(ElementType type, const ElementCoords& X, double rho, MassQuadrature quadrature) {
  const int n = checkedNodeCount(type, X);
  ScalarMatrix m;  // scalar mass, the same for each direction
  scalarMass(shapeTable(type, massLike(quadrature)), X, degenerateDetJ(X), m);
  ElementMatrix M = ElementMatrix::Zero(3 * n, 3 * n);
  addPerDirection(m, rho, M);
  return M;
}

ElementVector elementCentrifugalLoad(ElementType type, const ElementCoords& X, double rho, double omega,
                                     const RotationAxis& axis, MassQuadrature quadrature) {
  const int n = checkedNodeCount(type, X);
  const auto& t = shapeTable(type, massLike(quadrature));
  const double floor = degenerateDetJ(X);
  const Eigen::Vector3d a = unitAxis(axis);
  ElementVector f = ElementVector::Zero(3 * n);
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

ElementVector elementBodyLoad(ElementType type, const ElementCoords& X, const Eigen::Vector3d& b) {
  const int n = checkedNodeCount(type, X);
  const auto& t = shapeTable(type, Rule::Mass);
  const double floor = degenerateDetJ(X);
  Eigen::Matrix<double, Eigen::Dynamic, 1, Eigen::ColMajor, kMaxElementNodes, 1> nodal =
      Eigen::Matrix<double, Eigen::Dynamic, 1, Eigen::ColMajor, kMaxElementNodes, 1>::Zero(n);  // int N_a dV
  for (int q = 0; q < t.numPoints(); ++q) {
    double detJ;
    jacobian(t, q, X, floor, detJ);
    nodal += (t.weights[q] * detJ) * t.N[q];
  }
  ElementVector f(3 * n);
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

PointStresses elementStresses(ElementType type, const ElementCoords& X, const IsotropicElastic& mat,
                              const ElementVector& ue) {
  const int n = checkedNodeCount(type, X);
  if (ue.size() != 3 * n)
    throw Error("elementStresses: displacement vector of size " + std::to_string(ue.size()) + " for a " +
                mesh::exodusName(type) + " element of " + std::to_string(n) + " nodes");
  const auto& t = shapeTable(type, Rule::Stiffness);
  const double floor = degenerateDetJ(X);
  const Eigen::Matrix<double, 6, 6> D = mat.elasticity();
  StrainMatrix B = StrainMatrix::Zero(6, 3 * n);
  ElementCoords G(n, 3);
  PointStresses S(t.numPoints(), 6);
  for (int q = 0; q < t.numPoints(); ++q) {
    strainDisplacement(t, q, X, floor, G, B);
    const Eigen::Matrix<double, 6, 1> strain = B * ue;
    S.row(q) = (D * strain).transpose();
  }
  return S;
}

namespace {

Eigen::Matrix3d voigtTensor(const Eigen::Matrix<double, 1, 6>& s) {
  Eigen::Matrix3d S;
  S << s(0), s(5), s(4), s(5), s(1), s(3), s(4), s(3), s(2);
  return S;
}

}  // namespace

ElementMatrix elementGeometricStiffness(ElementType type, const ElementCoords& X, const PointStresses& stress) {
  const int n = checkedNodeCount(type, X);
  const auto& t = shapeTable(type, Rule::Stiffness);
  if (stress.rows() != t.numPoints())
    throw Error("elementGeometricStiffness: " + std::to_string(stress.rows()) + " stress rows for a rule of " +
                std::to_string(t.numPoints()) + " points");
  const double floor = degenerateDetJ(X);
  ScalarMatrix g = ScalarMatrix::Zero(n, n);  // scalar part, the same for each direction
  ElementCoords G(n, 3);
  for (int q = 0; q < t.numPoints(); ++q) {
    double detJ;
    const Eigen::Matrix3d J = jacobian(t, q, X, floor, detJ);
    G.noalias() = t.dN[q].lazyProduct(J.inverse());
    g.noalias() += (t.weights[q] * detJ) * (G * voigtTensor(stress.row(q)) * G.transpose());
  }
  symmetrize(g);
  ElementMatrix K = ElementMatrix::Zero(3 * n, 3 * n);
  addPerDirection(g, 1.0, K);
  return K;
}

ElementMatrix elementSpinSoftening(ElementType type, const ElementCoords& X, double rho, double omega,
                                   const RotationAxis& axis, MassQuadrature quadrature) {
  const int n = checkedNodeCount(type, X);
  const Eigen::Vector3d a = unitAxis(axis);
  const Eigen::Matrix3d P = Eigen::Matrix3d::Identity() - a * a.transpose();
  ScalarMatrix m;
  scalarMass(shapeTable(type, massLike(quadrature)), X, degenerateDetJ(X), m);
  ElementMatrix K(3 * n, 3 * n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) K.block<3, 3>(3 * i, 3 * j) = (rho * omega * omega * m(i, j)) * P;
  return K;
}

namespace {

// The Total Lagrangian strain variation operator at a point: row ij of node a,
// component k, (F_ki G_aj + F_kj G_ai) / (1 or 2).
void fillNonlinearB(const Eigen::Matrix3d& F, const ElementCoords& G, StrainMatrix& B) {
  for (Eigen::Index a = 0; a < G.rows(); ++a)
    for (int k = 0; k < 3; ++k) {
      const Eigen::Index c = 3 * a + k;
      B(0, c) = F(k, 0) * G(a, 0);
      B(1, c) = F(k, 1) * G(a, 1);
      B(2, c) = F(k, 2) * G(a, 2);
      B(3, c) = F(k, 1) * G(a, 2) + F(k, 2) * G(a, 1);
      B(4, c) = F(k, 0) * G(a, 2) + F(k, 2) * G(a, 0);
      B(5, c) = F(k, 0) * G(a, 1) + F(k, 1) * G(a, 0);
    }
}

// Deformation gradient and 2nd Piola-Kirchhoff stress (Voigt) at a point.
Eigen::Matrix<double, 6, 1> secondPiolaKirchhoff(const Eigen::Matrix<double, 6, 6>& D,
                                                 const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::ColMajor,
                                                                     kMaxElementNodes, 3>& U,
                                                 const ElementCoords& G, Eigen::Matrix3d& F) {
  F = Eigen::Matrix3d::Identity() + U.transpose() * G;
  const Eigen::Matrix3d E = 0.5 * (F.transpose() * F - Eigen::Matrix3d::Identity());
  Eigen::Matrix<double, 6, 1> e;
  e << E(0, 0), E(1, 1), E(2, 2), 2 * E(1, 2), 2 * E(0, 2), 2 * E(0, 1);
  return D * e;
}

}  // namespace

TotalLagrangianElement elementTotalLagrangian(ElementType type, const ElementCoords& X, const IsotropicElastic& mat,
                                              const ElementVector& ue, bool wantTangent) {
  const int n = checkedNodeCount(type, X);
  if (ue.size() != 3 * n) throw Error("elementTotalLagrangian: displacement vector of the wrong size");
  const auto& t = shapeTable(type, Rule::Stiffness);
  const double floor = degenerateDetJ(X);
  const Eigen::Matrix<double, 6, 6> D = mat.elasticity();
  TotalLagrangianElement out;
  out.internalForce = ElementVector::Zero(3 * n);
  if (wantTangent) out.tangent = ElementMatrix::Zero(3 * n, 3 * n);
  out.secondPK.resize(t.numPoints(), 6);
  out.cauchy.resize(t.numPoints(), 6);
  StrainMatrix B(6, 3 * n), DB(6, 3 * n);
  ElementCoords G(n, 3);
  ScalarMatrix g = ScalarMatrix::Zero(n, n);
  Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::ColMajor, kMaxElementNodes, 3> U(n, 3);
  for (int a = 0; a < n; ++a) U.row(a) = ue.segment<3>(3 * a).transpose();
  for (int q = 0; q < t.numPoints(); ++q) {
    double detJ;
    const Eigen::Matrix3d J = jacobian(t, q, X, floor, detJ);
    G.noalias() = t.dN[q].lazyProduct(J.inverse());  // dN/dX in the reference configuration
    Eigen::Matrix3d F;
    const Eigen::Matrix<double, 6, 1> S = secondPiolaKirchhoff(D, U, G, F);
    out.secondPK.row(q) = S.transpose();
    const Eigen::Matrix3d St = voigtTensor(S.transpose());
    const Eigen::Matrix3d sigma = F * St * F.transpose() / F.determinant();
    out.cauchy.row(q) << sigma(0, 0), sigma(1, 1), sigma(2, 2), sigma(1, 2), sigma(0, 2), sigma(0, 1);
    fillNonlinearB(F, G, B);
    const double w = t.weights[q] * detJ;
    out.internalForce.noalias() += w * (B.transpose() * S);
    if (wantTangent) {
      DB.noalias() = w * D * B;
      out.tangent.noalias() += B.transpose() * DB;
      g.noalias() += w * (G * St * G.transpose());
    }
  }
  if (wantTangent) {
    addPerDirection(g, 1.0, out.tangent);
    symmetrize(out.tangent);
  }
  return out;
}

void elementModalMatrices(ElementType type, const ElementCoords& X, const IsotropicElastic& mat,
                          const ElementPrestress& prestress, ElementMatrix& K, ElementMatrix* M,
                          MassQuadrature quadrature) {
  using Kind = ElementPrestress::Kind;
  const int n = checkedNodeCount(type, X);
  const auto& t = shapeTable(type, Rule::Stiffness);
  if (prestress.kind == Kind::Linear && (!prestress.stress || prestress.stress->rows() != t.numPoints()))
    throw Error("elementModalMatrices: a linear prestress needs the stress at the " + std::to_string(t.numPoints()) +
                " stiffness-rule points");
  if (prestress.kind == Kind::Nonlinear && (!prestress.displacement || prestress.displacement->size() != 3 * n))
    throw Error("elementModalMatrices: a nonlinear prestress needs the element's displacement (" +
                std::to_string(3 * n) + " values)");
  const double floor = degenerateDetJ(X);
  const Eigen::Matrix<double, 6, 6> D = mat.elasticity();
  K.setZero(3 * n, 3 * n);
  ScalarMatrix g = ScalarMatrix::Zero(n, n);  // the stress's share, the same in each direction
  StrainMatrix B = StrainMatrix::Zero(6, 3 * n), DB(6, 3 * n);
  ElementCoords G(n, 3);
  Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::ColMajor, kMaxElementNodes, 3> U(n, 3);
  if (prestress.kind == Kind::Nonlinear)
    for (int a = 0; a < n; ++a) U.row(a) = prestress.displacement->segment<3>(3 * a).transpose();
  for (int q = 0; q < t.numPoints(); ++q) {
    double detJ;
    const Eigen::Matrix3d J = jacobian(t, q, X, floor, detJ);
    G.noalias() = t.dN[q].lazyProduct(J.inverse());
    const double w = t.weights[q] * detJ;
    Eigen::Matrix3d St;
    if (prestress.kind == Kind::Nonlinear) {
      Eigen::Matrix3d F;
      St = voigtTensor(secondPiolaKirchhoff(D, U, G, F).transpose());
      fillNonlinearB(F, G, B);
    } else {
      fillB(G, B);
      if (prestress.kind == Kind::Linear) St = voigtTensor(prestress.stress->row(q));
    }
    DB.noalias() = w * D * B;
    K.noalias() += B.transpose() * DB;
    if (prestress.kind != Kind::None) g.noalias() += w * (G * St * G.transpose());
  }
  addPerDirection(g, 1.0, K);
  symmetrize(K);
  if (!M && prestress.omega == 0) return;
  ScalarMatrix m;
  scalarMass(shapeTable(type, massLike(quadrature)), X, floor, m);
  if (M) {
    M->setZero(3 * n, 3 * n);
    addPerDirection(m, mat.rho, *M);
  }
  if (prestress.omega != 0) {
    const Eigen::Vector3d a = unitAxis(prestress.axis);
    const Eigen::Matrix3d P = Eigen::Matrix3d::Identity() - a * a.transpose();
    const double rhoOmega2 = mat.rho * prestress.omega * prestress.omega;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) K.block<3, 3>(3 * i, 3 * j) -= (rhoOmega2 * m(i, j)) * P;
  }
}

double vonMises(const Eigen::Matrix<double, 6, 1>& s) {
  const double dxy = s[0] - s[1], dyz = s[1] - s[2], dzx = s[2] - s[0];
  return std::sqrt(0.5 * (dxy * dxy + dyz * dyz + dzx * dzx) + 3.0 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]));
}

}  // namespace cyclone::fe
