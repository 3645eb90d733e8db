#include "cyclone/fe/Material.hpp"

#include <sstream>

#include "cyclone/core/Error.hpp"

namespace cyclone::fe {

namespace {

std::string describe(const std::string& material, const char* parameter, double value) {
  std::ostringstream s;
  s.precision(17);
  s << "material '" << material << "': " << parameter << " = " << value;
  return s.str();
}

}  // namespace

void IsotropicElastic::validate(const std::string& where) const {
  // Written as !(ok) so that NaN fails too.
  if (!(E > 0)) throw InputError(where, describe(name, "Young's modulus E", E) + " must be positive");
  if (!(nu > -1 && nu < 0.5))
    throw InputError(where, describe(name, "Poisson's ratio nu", nu) + " must lie in (-1, 0.5)");
  if (!(rho >= 0)) throw InputError(where, describe(name, "density rho", rho) + " must not be negative");
}

Eigen::Matrix<double, 6, 6> IsotropicElastic::elasticity() const {
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
  const double mu = E / (2 * (1 + nu));
  Eigen::Matrix<double, 6, 6> D = Eigen::Matrix<double, 6, 6>::Zero();
  D.topLeftCorner<3, 3>().setConstant(lambda);
  for (int i = 0; i < 3; ++i) D(i, i) += 2 * mu;
  for (int i = 3; i < 6; ++i) D(i, i) = mu;  // engineering shear strain: tau = mu * gamma
  return D;
}

}  // namespace cyclone::fe
