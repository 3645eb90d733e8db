#include "cyclone/fe/Material.hpp"

#include <cmath>
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

const char* unitSystemName(UnitSystem units) {
  switch (units) {
    case UnitSystem::MillimetreNewtonSecondTonne: return "mm-N-s-t";
    case UnitSystem::SI: return "SI";
    case UnitSystem::Other: break;
  }
  return "other";
}

const char* stressUnitName(UnitSystem units) {
  switch (units) {
    case UnitSystem::MillimetreNewtonSecondTonne: return "MPa";
    case UnitSystem::SI: return "Pa";
    case UnitSystem::Other: break;
  }
  return "stress units";
}

double lengthUnitInMetres(UnitSystem units) {
  switch (units) {
    case UnitSystem::MillimetreNewtonSecondTonne: return 1e-3;
    case UnitSystem::SI: return 1;
    case UnitSystem::Other: break;
  }
  return 0;
}

double centrifugalStrainScale(const IsotropicElastic& material, double rpm, double radius) {
  const double omega = 2 * M_PI * rpm / 60;
  return material.rho * omega * omega * radius * radius / material.E;
}

double stressUnitInMpa(UnitSystem units) {
  switch (units) {
    case UnitSystem::MillimetreNewtonSecondTonne: return 1;
    case UnitSystem::SI: return 1e-6;
    case UnitSystem::Other: break;
  }
  return 0;
}

void IsotropicElastic::checkPlausible(const std::string& where) const {
  if (units == UnitSystem::Other) return;
  // In the set's own units: E in stress units, rho in mass per volume.
  const bool mm = units == UnitSystem::MillimetreNewtonSecondTonne;
  const double eLow = mm ? 1e2 : 1e8, eHigh = mm ? 2e6 : 2e12;
  const double rhoLow = mm ? 1e-10 : 1e2, rhoHigh = mm ? 3e-8 : 3e4;
  const std::string set = std::string(" in the ") + unitSystemName(units) + " set (";
  if (!(E >= eLow && E <= eHigh))
    throw InputError(where, describe(name, "Young's modulus E", E) + " is no solid's" + set + stressUnitName(units) +
                                "; from " + (mm ? "1e2 to 2e6" : "1e8 to 2e12") +
                                "): a value in other units? Give units: SI, mm-N-s-t or other");
  // Towards nu = 0.5 the displacement-only elements lock: their volumetric stiffness grows
  // as 1 / (1 - 2 nu) and the answers come out too stiff without a word (a fifth probe ran
  // nu = 0.49999). A disc alloy's nu lies near 0.3; 0.45 leaves room for polymers.
  if (nu > 0.45)
    throw InputError(where, describe(name, "Poisson's ratio nu", nu) +
                                " is nearly incompressible: the displacement elements (tet4, tet10, hex8, hex20) lock "
                                "there (their volumetric stiffness grows as 1 / (1 - 2 nu)) and would give too stiff an "
                                "answer; a disc alloy's nu lies near 0.3 (units: other takes any nu below 0.5)");
  if (!(rho == 0 || (rho >= rhoLow && rho <= rhoHigh)))  // 0: a static analysis without mass
    throw InputError(where, describe(name, "density rho", rho) + " is no solid's" + set +
                                (mm ? "t/mm^3; from 1e-10 to 3e-8" : "kg/m^3; from 1e2 to 3e4") +
                                "): a value in other units? Give units: SI, mm-N-s-t or other");
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
