#pragma once
#include <Eigen/Dense>
#include <string>

namespace cyclone::fe {

/// Isotropic linear elastic material in a consistent unit set (examples: mm, N, s, t).
struct IsotropicElastic {
  std::string name = "titanium";
  double E = 1.16e5;      ///< Young's modulus (MPa)
  double nu = 0.34;       ///< Poisson's ratio
  double rho = 4.507e-9;  ///< density (t/mm^3)

  /// Throws InputError naming the parameter if E <= 0, rho < 0 or nu outside (-1, 0.5).
  void validate(const std::string& where) const;
  /// 6x6 elasticity matrix in Voigt order xx, yy, zz, yz, xz, xy with engineering shear strains.
  Eigen::Matrix<double, 6, 6> elasticity() const;
};

}  // namespace cyclone::fe
