#pragma once
// Element kernels: pure functions of the element's node coordinates and the
// material. No mesh, no Trilinos. Element DOFs are node-major:
// [u0x u0y u0z u1x ...]. Node order is Exodus order (ElementType.hpp).
#include <Eigen/Dense>

#include "cyclone/core/Error.hpp"
#include "cyclone/fe/Material.hpp"
#include "cyclone/mesh/ElementType.hpp"
#include "cyclone/mesh/RotatedNodePairing.hpp"

namespace cyclone::fe {

using mesh::ElementType;
using ElementCoords = Eigen::Matrix<double, Eigen::Dynamic, 3>;  // n x 3

using mesh::RotationAxis;

/// Thrown when det J <= 0 at an integration point; the assembler adds the element id.
/// A det J below 1e-14 h^3 (h the element's bounding-box diagonal) counts as zero: that
/// element is flat to round-off.
class InvalidElementGeometry : public Error {
public:
  InvalidElementGeometry(int point, double detJ);
  int point;
  double detJ;
};

/// Linear elastic stiffness (3n x 3n), stiffnessRule.
Eigen::MatrixXd elementStiffness(ElementType type, const ElementCoords& X, const IsotropicElastic& mat);
/// Consistent mass (3n x 3n), massRule (or stiffnessRule: MassQuadrature).
Eigen::MatrixXd elementMass(ElementType type, const ElementCoords& X, double rho,
                            MassQuadrature quadrature = MassQuadrature::Exact);
/// Consistent centrifugal body load  int N^T rho Omega^2 r_perp dV  (3n), r_perp the
/// distance vector from the axis at the undeformed position; massRule (or stiffnessRule).
Eigen::VectorXd elementCentrifugalLoad(ElementType type, const ElementCoords& X, double rho, double omega,
                                       const RotationAxis& axis, MassQuadrature quadrature = MassQuadrature::Exact);
/// Consistent load of a uniform body force density b (force/volume) (3n).
Eigen::VectorXd elementBodyLoad(ElementType type, const ElementCoords& X, const Eigen::Vector3d& b);
/// Element volume.
double elementVolume(ElementType type, const ElementCoords& X);
/// Small-strain Cauchy stress (Voigt xx yy zz yz xz xy) at each stiffness-rule point for the
/// element displacement vector ue (3n); one row per point.
Eigen::Matrix<double, Eigen::Dynamic, 6> elementStresses(ElementType type, const ElementCoords& X,
                                                         const IsotropicElastic& mat, const Eigen::VectorXd& ue);
/// Geometric (stress) stiffness for a stress state given at the stiffness-rule points
/// (one Voigt row per point, e.g. from elementStresses):
///   K_ab = (int grad N_a . S grad N_b dV) I_3   (stiffness rule).
Eigen::MatrixXd elementGeometricStiffness(ElementType type, const ElementCoords& X,
                                          const Eigen::Matrix<double, Eigen::Dynamic, 6>& stress);
/// Spin softening: the centrifugal load's change with displacement,
///   K_ab = rho Omega^2 (int N_a N_b dV) (I - a a^T)   (mass rule),
/// subtracted from the tangent (the load follows the deformed position).
Eigen::MatrixXd elementSpinSoftening(ElementType type, const ElementCoords& X, double rho, double omega,
                                     const RotationAxis& axis, MassQuadrature quadrature = MassQuadrature::Exact);
/// Geometrically nonlinear element (Total Lagrangian, St Venant-Kirchhoff) at the
/// element displacement ue, stiffness rule: Green-Lagrange strain E = (F^T F - I)/2,
/// second Piola-Kirchhoff stress S = D E,
///   internal force  f = int B(u)^T S dV0,
///   tangent         K = int B(u)^T D B(u) dV0 + int G^T S G dV0 (material + geometric),
/// with B(u) the strain variation operator (F^T-weighted gradients).
struct TotalLagrangianElement {
  Eigen::VectorXd internalForce;
  Eigen::MatrixXd tangent;                          ///< empty unless asked for
  Eigen::Matrix<double, Eigen::Dynamic, 6> secondPK;  ///< per stiffness-rule point
  Eigen::Matrix<double, Eigen::Dynamic, 6> cauchy;    ///< sigma = F S F^T / det F, per point
};
TotalLagrangianElement elementTotalLagrangian(ElementType type, const ElementCoords& X, const IsotropicElastic& mat,
                                              const Eigen::VectorXd& ue, bool wantTangent);

/// von Mises equivalent of a Voigt stress.
double vonMises(const Eigen::Matrix<double, 6, 1>& s);

}  // namespace cyclone::fe
