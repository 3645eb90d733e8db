// Describing functions of the scalar elements under w = A cos tau against
// closed forms integrated by hand over one period.
#include "cyclone/core/Error.hpp"
#include "cyclone/hbm/Aft.hpp"
#include "cyclone/hbm/CubicSpring.hpp"
#include "cyclone/hbm/HarmonicForce.hpp"
#include "cyclone/hbm/JenkinsElement.hpp"
#include "cyclone/hbm/QuadraticDamper.hpp"
#include "cyclone/hbm/UnilateralSpring.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

using namespace cyclone::hbm;

namespace {

constexpr double kPi = 3.14159265358979323846;

// Coefficients of w = amplitude cos tau in the layout of `set`.
Eigen::VectorXd cosine(const HarmonicSet& set, double amplitude) {
  Eigen::VectorXd w = Eigen::VectorXd::Zero(set.numCoefficients());
  w[set.cosIndex(1)] = amplitude;
  return w;
}

// Jenkins element under u = U cos tau. Over tau in [0, pi] the loop is: stick
// from the turning point, f = Fs - kt U (1 - cos tau), until f = -Fs at phi0
// with kt U (1 - cos phi0) = 2 Fs; then slip at -Fs up to pi. The second half
// is the negative (f(tau + pi) = -f(tau)), so only odd harmonics appear and
//   a1 = (2/pi) int_0^pi f cos = (kt U / pi) (phi0 - sin(2 phi0) / 2),
//   b1 = (2/pi) int_0^pi f sin = -(kt U / pi) sin^2(phi0),
// using 2 Fs - kt U = -kt U cos phi0 to simplify. (Valid when kt U > Fs.)
struct JenkinsFirstHarmonic {
  double cos, sin;
};
JenkinsFirstHarmonic jenkinsClosedForm(double kt, double slipForce, double u) {
  const double phi0 = std::acos(1.0 - 2.0 * slipForce / (kt * u));
  return {kt * u / kPi * (phi0 - std::sin(2 * phi0) / 2), -kt * u / kPi * std::sin(phi0) * std::sin(phi0)};
}

}  // namespace

TEST(CubicSpring, CosineGivesThreeQuartersAndOneQuarter) {
  const double k3 = 1.7, a = 0.9;
  for (int n : {16, 64}) {
    const Aft aft(HarmonicSet::upTo(5), n);
    const Eigen::VectorXd f = harmonicForce(CubicSpring(k3), aft, cosine(aft.harmonics(), a));
    Eigen::VectorXd expected = Eigen::VectorXd::Zero(f.size());
    expected[aft.harmonics().cosIndex(1)] = 0.75 * k3 * a * a * a;  // cos^3 = 3/4 cos + 1/4 cos 3
    expected[aft.harmonics().cosIndex(3)] = 0.25 * k3 * a * a * a;
    EXPECT_LT((f - expected).cwiseAbs().maxCoeff(), 1e-14) << "N = " << n;
  }
}

TEST(JenkinsElement, ClosedFormMatchesTheQuotedDescribingFunction) {
  // Guards the derivation above with the numbers given in the issue.
  const JenkinsFirstHarmonic c = jenkinsClosedForm(2.0, 3.0, 5.0);
  EXPECT_NEAR(c.cos, 2.523158, 5e-7);
  EXPECT_NEAR(c.sin, -2.673803, 5e-7);
}

TEST(JenkinsElement, DescribingFunctionConvergesWithSamples) {
  const double kt = 2.0, slipForce = 3.0, u = 5.0;
  const JenkinsElement element(kt, slipForce);
  const JenkinsFirstHarmonic exact = jenkinsClosedForm(kt, slipForce, u);
  std::vector<double> errors;
  const std::vector<int> samples{64, 256, 1024, 4096, 16384};
  for (int n : samples) {
    const Aft aft(HarmonicSet::upTo(3), n);
    const Eigen::VectorXd f = harmonicForce(element, aft, cosine(aft.harmonics(), u));
    const double c = f[aft.harmonics().cosIndex(1)], s = f[aft.harmonics().sinIndex(1)];
    const double error = std::max(std::abs(c - exact.cos), std::abs(s - exact.sin));
    std::printf("Jenkins N = %6d: cos %.9f sin %.9f  error %.3e\n", n, c, s, error);
    errors.push_back(error);
    // Half-wave antisymmetry: no mean and no even harmonic.
    EXPECT_LT(std::abs(f[aft.harmonics().cosIndex(0)]), 1e-12);
    EXPECT_LT(std::abs(f[aft.harmonics().cosIndex(2)]), 1e-12);
    EXPECT_LT(std::abs(f[aft.harmonics().sinIndex(2)]), 1e-12);
    if (n == 16384) {
      EXPECT_NEAR(c, 2.523158, 5e-7);
      EXPECT_NEAR(s, -2.673803, 5e-7);
      EXPECT_NEAR(c, exact.cos, 1e-6);
      EXPECT_NEAR(s, exact.sin, 1e-6);
    }
  }
  // At least first order: N * error does not grow beyond its value at N = 64.
  for (std::size_t i = 1; i < samples.size(); ++i)
    EXPECT_LE(errors[i] * samples[i], errors[0] * samples[0]) << "N = " << samples[i];
}

TEST(JenkinsElement, StuckElementIsALinearSpring) {
  const double kt = 2.0;
  const Aft aft(HarmonicSet::upTo(3), 32);
  const Eigen::VectorXd w = cosine(aft.harmonics(), 1.0);  // kt U = 2 < slip force 3
  const Eigen::VectorXd f = harmonicForce(JenkinsElement(kt, 3.0), aft, w);
  EXPECT_LT((f - kt * w).cwiseAbs().maxCoeff(), 1e-14);
}

TEST(UnilateralSpring, ClippedCosineClosedForm) {
  // f = k (A cos tau - g) where cos tau > g / A, i.e. |tau| < alpha = acos(g / A):
  //   mean a0 = (1/2pi) int_-alpha^alpha k (A cos - g) = (k / pi) (A sin alpha - g alpha),
  //   a1 = (1/pi) int_-alpha^alpha k (A cos - g) cos = (k A / pi) (alpha - sin alpha cos alpha),
  // using g = A cos alpha; b1 = 0 by symmetry.
  const double k = 3.5, a = 1.3, g = 0.4;
  const double alpha = std::acos(g / a);
  const double mean = k / kPi * (a * std::sin(alpha) - g * alpha);
  const double first = k * a / kPi * (alpha - std::sin(alpha) * std::cos(alpha));
  const Aft aft(HarmonicSet::upTo(3), 16384);
  const Eigen::VectorXd f = harmonicForce(UnilateralSpring(k, g), aft, cosine(aft.harmonics(), a));
  EXPECT_NEAR(f[aft.harmonics().cosIndex(0)], mean, 1e-5);
  EXPECT_NEAR(f[aft.harmonics().cosIndex(1)], first, 1e-5);
  EXPECT_NEAR(f[aft.harmonics().sinIndex(1)], 0.0, 1e-12);
}

TEST(UnilateralSpring, InterferenceIsAPreload) {
  // gap < 0 with A < -gap: always in contact, f = k (w - gap).
  const double k = 2.0, gap = -1.0;
  const Aft aft(HarmonicSet::upTo(2), 16);
  const Eigen::VectorXd w = cosine(aft.harmonics(), 0.5);
  Eigen::VectorXd expected = k * w;
  expected[aft.harmonics().cosIndex(0)] = -k * gap;
  EXPECT_LT((harmonicForce(UnilateralSpring(k, gap), aft, w) - expected).cwiseAbs().maxCoeff(), 1e-14);
}

TEST(QuadraticDamper, CosineClosedForm) {
  // w = A cos tau, dw/dt = -omega A sin tau, f = -c2 omega^2 A^2 sin|sin|;
  // b1 = (1/pi) int f sin = -c2 omega^2 A^2 (2/pi) int_0^pi sin^3 = -8/(3 pi) c2 omega^2 A^2.
  const double c2 = 0.7, a = 1.2, omega = 2.5;
  const Aft aft(HarmonicSet::upTo(3), 8192);
  const Eigen::VectorXd f =
      harmonicForce(QuadraticDamper(c2), aft, cosine(aft.harmonics(), a), nullptr, omega);
  EXPECT_NEAR(f[aft.harmonics().sinIndex(1)], -8.0 / (3 * kPi) * c2 * omega * omega * a * a, 1e-6);
  EXPECT_NEAR(f[aft.harmonics().cosIndex(1)], 0.0, 1e-12);
}

TEST(ScalarElements, RejectBadParameters) {
  using cyclone::InputError;
  EXPECT_THROW(JenkinsElement(0.0, 1.0), InputError);
  EXPECT_THROW(JenkinsElement(1.0, -1.0), InputError);
  EXPECT_THROW(UnilateralSpring(-1.0, 0.0), InputError);
  EXPECT_THROW(QuadraticDamper(-0.1), InputError);
  EXPECT_THROW(CubicSpring(std::nan("")), InputError);
}
