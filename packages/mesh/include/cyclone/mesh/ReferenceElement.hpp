#pragma once
// Isoparametric reference elements: shape functions, their derivatives in the
// reference coordinates, and Gauss rules. Pure functions of the reference point.
// Reference domains: tets on {xi,eta,zeta >= 0, xi+eta+zeta <= 1} with corner 0
// at the origin and corners 1,2,3 on the xi, eta, zeta axes; hexes on [-1,1]^3
// with corners in Exodus order.
#include <Eigen/Dense>
#include <vector>

#include "cyclone/mesh/ElementType.hpp"

namespace cyclone::mesh {

using ShapeValues = Eigen::VectorXd;                           // n
using ShapeGradients = Eigen::Matrix<double, Eigen::Dynamic, 3>;  // n x 3, d N_i / d xi_j

void evaluateShape(ElementType type, const Eigen::Vector3d& xi, ShapeValues& N, ShapeGradients& dN);

/// Reference coordinates of the element's nodes (n x 3).
Eigen::Matrix<double, Eigen::Dynamic, 3> referenceNodes(ElementType type);

struct QuadratureRule {
  std::vector<Eigen::Vector3d> points;
  std::vector<double> weights;  ///< sum = reference volume (1/6 tet, 8 hex)
  int degree = 0;               ///< polynomials up to this degree are integrated exactly
  const char* name = "";
};

/// Rule for stiffness (exact for the undistorted element's stiffness integrand):
///   tet4 1-point, tet10 4-point (degree 2), hex8 2x2x2, hex20 3x3x3.
const QuadratureRule& stiffnessRule(ElementType type);
/// Rule for consistent mass (exact for N_i N_j on undistorted elements):
///   tet4 4-point (degree 2), tet10 degree-4 rule, hex8 2x2x2, hex20 3x3x3.
const QuadratureRule& massRule(ElementType type);

/// Smallest det(dx/dxi) over the stiffness and mass rules' points and the element's nodes
/// (coords: n x 3 rows in element order). <= 0 means inverted or degenerate.
double minJacobianDeterminant(ElementType type, const Eigen::Matrix<double, Eigen::Dynamic, 3>& coords);

}  // namespace cyclone::mesh
