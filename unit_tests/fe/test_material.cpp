// Isotropic elasticity: the stiffness matrix inverts the textbook compliance, and
// validation rejects non-physical parameters with a message naming them.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "cyclone/core/Error.hpp"
#include "cyclone/fe/Material.hpp"

using cyclone::InputError;
using cyclone::fe::IsotropicElastic;
using cyclone::fe::UnitSystem;

namespace {

// Compliance eps = S sigma: eps_xx = (s_xx - nu (s_yy + s_zz)) / E, gamma = 2 (1 + nu) tau / E.
Eigen::Matrix<double, 6, 6> compliance(double E, double nu) {
  Eigen::Matrix<double, 6, 6> S = Eigen::Matrix<double, 6, 6>::Zero();
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) S(i, j) = -nu / E;
    S(i, i) = 1 / E;
    S(i + 3, i + 3) = 2 * (1 + nu) / E;
  }
  return S;
}

TEST(IsotropicElastic, ElasticityInvertsTheCompliance) {
  for (double nu : {-0.5, 0.0, 0.3, 0.34, 0.49}) {
    IsotropicElastic m;
    m.E = 2.1e5;
    m.nu = nu;
    const Eigen::Matrix<double, 6, 6> product = m.elasticity() * compliance(m.E, nu);
    EXPECT_LT((product - Eigen::Matrix<double, 6, 6>::Identity()).cwiseAbs().maxCoeff(), 1e-12) << "nu = " << nu;
  }
}

TEST(IsotropicElastic, UniaxialStressGivesYoungsModulusAndPoissonContraction) {
  IsotropicElastic m;  // titanium defaults
  Eigen::Matrix<double, 6, 1> strain;
  strain << 1e-3, -m.nu * 1e-3, -m.nu * 1e-3, 0, 0, 0;
  const Eigen::Matrix<double, 6, 1> stress = m.elasticity() * strain;
  EXPECT_NEAR(stress[0], m.E * 1e-3, 1e-9 * m.E);
  for (int i = 1; i < 6; ++i) EXPECT_NEAR(stress[i], 0.0, 1e-12 * m.E);
}

TEST(IsotropicElastic, ValidateAcceptsDefaults) { EXPECT_NO_THROW(IsotropicElastic().validate("scene.yaml")); }

void expectRejected(const IsotropicElastic& m, const std::string& parameter) {
  try {
    m.validate("scene.yaml:7");
    FAIL() << "accepted " << parameter;
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "scene.yaml:7");
    EXPECT_NE(std::string(e.what()).find(parameter), std::string::npos) << e.what();
  }
}

TEST(IsotropicElastic, ValidateRejectsNonPhysicalParameters) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (double E : {0.0, -1.0, nan}) {
    IsotropicElastic m;
    m.E = E;
    expectRejected(m, "Young's modulus");
  }
  for (double nu : {0.5, 0.6, -1.0, nan}) {
    IsotropicElastic m;
    m.nu = nu;
    expectRejected(m, "Poisson's ratio");
  }
  IsotropicElastic m;
  m.rho = -1e-9;
  expectRejected(m, "density");
}

// A nearly incompressible nu is refused as implausible for the displacement elements (a
// fifth probe ran nu = 0.49999 with no word), naming nu; a set the code cannot name
// (units: other) takes it, and 0.45 passes.
TEST(IsotropicElastic, PlausibilityRefusesANearlyIncompressibleNu) {
  IsotropicElastic m;
  m.nu = 0.49999;
  EXPECT_NO_THROW(m.validate("scene.yaml"));
  try {
    m.checkPlausible("cyclone/material");
    ADD_FAILURE() << "nu = 0.49999 accepted";
  } catch (const cyclone::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("Poisson's ratio nu"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("nearly incompressible"), std::string::npos) << e.what();
  }
  m.nu = 0.45;
  EXPECT_NO_THROW(m.checkPlausible("cyclone/material"));
  m.nu = 0.49999;
  m.units = cyclone::fe::UnitSystem::Other;
  EXPECT_NO_THROW(m.checkPlausible("cyclone/material"));
}

}  // namespace

// The unit sets' length: a millimetre and a metre; none for a set the code cannot name.
TEST(UnitSystem, LengthUnitInMetres) {
  EXPECT_EQ(cyclone::fe::lengthUnitInMetres(UnitSystem::MillimetreNewtonSecondTonne), 1e-3);
  EXPECT_EQ(cyclone::fe::lengthUnitInMetres(UnitSystem::SI), 1.0);
  EXPECT_EQ(cyclone::fe::lengthUnitInMetres(UnitSystem::Other), 0.0);
}

// rho (Omega r)^2 / E by hand: 60 rpm is Omega = 2 pi rad/s; with rho = 2, r = 3, E = 4 pi^2
// the scale is 2 (2 pi 3)^2 / (4 pi^2) = 18.
TEST(IsotropicElastic, CentrifugalStrainScaleIsRhoOmegaRSquaredOverE) {
  IsotropicElastic m;
  m.rho = 2, m.E = 4 * M_PI * M_PI;
  EXPECT_NEAR(cyclone::fe::centrifugalStrainScale(m, 60, 3), 18.0, 1e-13);
  EXPECT_EQ(cyclone::fe::centrifugalStrainScale(m, 0, 3), 0.0);
  // Titanium (the default material) at 10000 rpm and 200 mm, in mm-N-s-t:
  // 4.507e-9 (1047.1976 x 200)^2 / 1.16e5 = 1.70430e-3, by hand.
  EXPECT_NEAR(cyclone::fe::centrifugalStrainScale(IsotropicElastic(), 10000, 200), 1.70430e-3, 1e-8);
}
