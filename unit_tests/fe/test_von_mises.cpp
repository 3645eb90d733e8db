// von Mises equivalent stress against uniaxial and shear closed forms and the
// principal-stress formula.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "cyclone/fe/ElementKernels.hpp"

using cyclone::fe::vonMises;
using Voigt = Eigen::Matrix<double, 6, 1>;

namespace {

TEST(VonMises, UniaxialStressGivesItsMagnitude) {
  for (int i = 0; i < 3; ++i)
    for (double s : {250.0, -130.0}) {
      Voigt v = Voigt::Zero();
      v[i] = s;
      EXPECT_NEAR(vonMises(v), std::abs(s), 1e-12 * std::abs(s));
    }
}

TEST(VonMises, PureShearGivesSqrt3TimesTheShear) {
  for (int i = 3; i < 6; ++i) {
    Voigt v = Voigt::Zero();
    v[i] = -40.0;
    EXPECT_NEAR(vonMises(v), std::sqrt(3.0) * 40.0, 1e-12);
  }
}

TEST(VonMises, HydrostaticStressGivesZero) {
  Voigt v;
  v << 70, 70, 70, 0, 0, 0;
  EXPECT_NEAR(vonMises(v), 0.0, 1e-12);
}

// sqrt(((s1-s2)^2 + (s2-s3)^2 + (s3-s1)^2) / 2) from the principal stresses.
TEST(VonMises, MatchesPrincipalStressFormula) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-100, 100);
  for (int k = 0; k < 20; ++k) {
    Voigt v;
    for (int i = 0; i < 6; ++i) v[i] = u(rng);
    Eigen::Matrix3d T;
    T << v[0], v[5], v[4], v[5], v[1], v[3], v[4], v[3], v[2];
    const Eigen::Vector3d s = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(T).eigenvalues();
    const double expected =
        std::sqrt(0.5 * ((s[0] - s[1]) * (s[0] - s[1]) + (s[1] - s[2]) * (s[1] - s[2]) + (s[2] - s[0]) * (s[2] - s[0])));
    EXPECT_NEAR(vonMises(v), expected, 1e-10 * expected);
  }
}

}  // namespace
