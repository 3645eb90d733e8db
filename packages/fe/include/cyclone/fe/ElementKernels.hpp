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

/// Element-sized arrays keep their storage inside the object (Eigen's fixed maximum
/// sizes): a kernel called per element and per integration point allocates nothing.
constexpr int kMaxElementNodes = 20, kMaxElementDofs = 3 * kMaxElementNodes;
constexpr int kMaxRulePoints = 27;  ///< the largest rule: 3 x 3 x 3 Gauss (hex20)
using ElementCoords = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::ColMajor, kMaxElementNodes, 3>;  // n x 3
using ElementMatrix =
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::ColMajor, kMaxElementDofs, kMaxElementDofs>;
using ElementVector = Eigen::Matrix<double, Eigen::Dynamic, 1, Eigen::ColMajor, kMaxElementDofs, 1>;
/// One Voigt row per integration point.
using PointStresses = Eigen::Matrix<double, Eigen::Dynamic, 6, Eigen::ColMajor, kMaxRulePoints, 6>;

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
ElementMatrix elementStiffness(ElementType type, const ElementCoords& X, const IsotropicElastic& mat);
/// Consistent mass (3n x 3n), massRule (or stiffnessRule: MassQuadrature).
ElementMatrix elementMass(ElementType type, const ElementCoords& X, double rho,
                            MassQuadrature quadrature = MassQuadrature::Exact);
/// Consistent centrifugal body load  int N^T rho Omega^2 r_perp dV  (3n), r_perp the
/// distance vector from the axis at the undeformed position; massRule (or stiffnessRule).
ElementVector elementCentrifugalLoad(ElementType type, const ElementCoords& X, double rho, double omega,
                                       const RotationAxis& axis, MassQuadrature quadrature = MassQuadrature::Exact);
/// Consistent load of a uniform body force density b (force/volume) (3n).
ElementVector elementBodyLoad(ElementType type, const ElementCoords& X, const Eigen::Vector3d& b);
/// Element volume.
double elementVolume(ElementType type, const ElementCoords& X);
/// Small-strain Cauchy stress (Voigt xx yy zz yz xz xy) at each stiffness-rule point for the
/// element displacement vector ue (3n); one row per point.
PointStresses elementStresses(ElementType type, const ElementCoords& X, const IsotropicElastic& mat,
                              const ElementVector& ue);
/// Geometric (stress) stiffness for a stress state given at the stiffness-rule points
/// (one Voigt row per point, e.g. from elementStresses):
///   K_ab = (int grad N_a . S grad N_b dV) I_3   (stiffness rule).
ElementMatrix elementGeometricStiffness(ElementType type, const ElementCoords& X, const PointStresses& stress);
/// Spin softening: the centrifugal load's change with displacement,
///   K_ab = rho Omega^2 (int N_a N_b dV) (I - a a^T)   (mass rule),
/// subtracted from the tangent (the load follows the deformed position).
ElementMatrix elementSpinSoftening(ElementType type, const ElementCoords& X, double rho, double omega,
                                     const RotationAxis& axis, MassQuadrature quadrature = MassQuadrature::Exact);
/// Geometrically nonlinear element (Total Lagrangian, St Venant-Kirchhoff) at the
/// element displacement ue, stiffness rule: Green-Lagrange strain E = (F^T F - I)/2,
/// second Piola-Kirchhoff stress S = D E,
///   internal force  f = int B(u)^T S dV0,
///   tangent         K = int B(u)^T D B(u) dV0 + int G^T S G dV0 (material + geometric),
/// with B(u) the strain variation operator (F^T-weighted gradients).
struct TotalLagrangianElement {
  ElementVector internalForce;
  ElementMatrix tangent;   ///< empty unless asked for
  PointStresses secondPK;  ///< per stiffness-rule point
  PointStresses cauchy;    ///< sigma = F S F^T / det F, per point
};
TotalLagrangianElement elementTotalLagrangian(ElementType type, const ElementCoords& X, const IsotropicElastic& mat,
                                              const ElementVector& ue, bool wantTangent);

/// The prestress one element's modal tangent carries (ElementModalMatrices).
struct ElementPrestress {
  enum class Kind { None, Linear, Nonlinear } kind = Kind::None;
  const PointStresses* stress = nullptr;       ///< Linear: small-strain stress at the stiffness-rule points
  const ElementVector* displacement = nullptr;  ///< Nonlinear: the element's displacement (3n)
  double omega = 0;                             ///< spin softening -K_Omega at this speed (rad/s); 0: none
  RotationAxis axis;
};

/// The modal tangent K (+ K_sigma, or the Total Lagrangian tangent, - K_Omega) and,
/// when M is given, the consistent mass, in one pass: J^-1 and w det J once per point of
/// each rule, shared by K, K_sigma and the TL tangent (stiffness rule) and by M and
/// K_Omega (mass rule). The same matrices as the single-term kernels summed, to rounding.
void elementModalMatrices(ElementType type, const ElementCoords& X, const IsotropicElastic& mat,
                          const ElementPrestress& prestress, ElementMatrix& K, ElementMatrix* M,
                          MassQuadrature quadrature = MassQuadrature::Exact);

/// von Mises equivalent of a Voigt stress.
double vonMises(const Eigen::Matrix<double, 6, 1>& s);

}  // namespace cyclone::fe
