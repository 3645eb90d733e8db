#pragma once
#include <Eigen/Dense>
#include <string>

namespace cyclone::fe {

/// How the mass-like element terms (consistent mass, centrifugal load, spin softening)
/// are integrated. Exact: the element's mass rule (14 points for tet10, exact for its
/// quadratic shape functions' products). StiffnessRule: the stiffness rule (4 points for
/// tet10), which CalculiX uses for C3D10's mass and centrifugal load: for comparing with
/// it at its own discretisation (docs/verification.md), not for accuracy.
enum class MassQuadrature { Exact, StiffnessRule };

/// Isotropic linear elastic material in a consistent unit set (examples: mm, N, s, t).
struct IsotropicElastic {
  std::string name = "titanium";
  double E = 1.16e5;      ///< Young's modulus (MPa)
  double nu = 0.34;       ///< Poisson's ratio
  double rho = 4.507e-9;  ///< density (t/mm^3)
  MassQuadrature massQuadrature = MassQuadrature::Exact;

  /// Throws InputError naming the parameter if E <= 0, rho < 0 or nu outside (-1, 0.5).
  void validate(const std::string& where) const;
  /// 6x6 elasticity matrix in Voigt order xx, yy, zz, yz, xz, xy with engineering shear strains.
  Eigen::Matrix<double, 6, 6> elasticity() const;
};

}  // namespace cyclone::fe
