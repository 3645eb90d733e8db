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

/// The consistent unit set a material's numbers are in: what makes a stress a number of
/// MPa (fatigue data by name, plot labels) and what values are plausible. Other: any
/// consistent set the code cannot name (no fatigue data by name, no plausibility check).
enum class UnitSystem { MillimetreNewtonSecondTonne, SI, Other };
/// "mm-N-s-t", "SI", "other".
const char* unitSystemName(UnitSystem units);
/// "MPa", "Pa", "stress units".
const char* stressUnitName(UnitSystem units);
/// One stress unit in MPa (1, 1e-6); 0 for Other.
double stressUnitInMpa(UnitSystem units);
/// One length unit in metres (1e-3, 1); 0 for Other.
double lengthUnitInMetres(UnitSystem units);

/// Isotropic linear elastic material in a consistent unit set (examples: mm, N, s, t).
struct IsotropicElastic {
  std::string name = "titanium";
  double E = 1.16e5;      ///< Young's modulus (MPa)
  double nu = 0.34;       ///< Poisson's ratio
  double rho = 4.507e-9;  ///< density (t/mm^3)
  MassQuadrature massQuadrature = MassQuadrature::Exact;
  UnitSystem units = UnitSystem::MillimetreNewtonSecondTonne;

  /// Throws InputError naming the parameter if E <= 0, rho < 0 or nu outside (-1, 0.5).
  void validate(const std::string& where) const;
  /// Throws InputError naming E or rho where its value is no solid's in `units` (E from
  /// 1e2 to 2e6 MPa, rho from 1e2 to 3e4 kg/m^3; a modulus in Pa with the mm-N-s-t set is
  /// a million times too stiff). Nothing for UnitSystem::Other.
  void checkPlausible(const std::string& where) const;
  /// 6x6 elasticity matrix in Voigt order xx, yy, zz, yz, xz, xy with engineering shear strains.
  Eigen::Matrix<double, 6, 6> elasticity() const;
};

/// The centrifugal stress scale rho (Omega r)^2 at `radius` and `rpm` over E: the strain
/// the spin alone puts there (titanium bursts near 1 %).
double centrifugalStrainScale(const IsotropicElastic& material, double rpm, double radius);

}  // namespace cyclone::fe
