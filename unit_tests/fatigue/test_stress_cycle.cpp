// The cycle measures against closed forms: a proportional uniaxial cycle, two
// normal stresses 90 degrees apart (von Mises sqrt(3/2) a, not a), pure shear,
// a second harmonic adding to the first, and the sign of a compressive mean.
#include <gtest/gtest.h>

#include <cmath>

#include "cyclone/core/Error.hpp"
#include "cyclone/fatigue/StressCycle.hpp"

using namespace cyclone::fatigue;

namespace {
HarmonicStress harmonic(int h, int component, std::complex<double> a) {
  HarmonicStress s;
  s.harmonic = h;
  s.amplitude(component) = a;
  return s;
}
}  // namespace

TEST(StressCycle, ProportionalUniaxialCycleIsItsAmplitude) {
  Voigt mean = Voigt::Zero();
  mean(0) = 200;
  const auto m = measureCycle(mean, {harmonic(1, 0, std::polar(50.0, 0.7))});
  EXPECT_NEAR(m.alternatingVonMises, 50, 1e-9 * 50);
  EXPECT_NEAR(m.alternatingPrincipal, 50, 1e-9 * 50);
  EXPECT_NEAR(m.meanVonMises, 200, 1e-12);
  EXPECT_NEAR(m.maxVonMises, 250, 1e-9 * 250);
}

TEST(StressCycle, NormalStressesOutOfPhaseHaveALargerVonMises) {
  // s_xx = a cos t, s_yy = a sin t: vM^2 = a^2 (1 - sin(2t) / 2), largest a sqrt(3/2);
  // the principal stresses are the two components, at most a.
  const double a = 80;
  const auto m = measureCycle(Voigt::Zero(), {[&] {
                                auto s = harmonic(1, 0, a);
                                s.amplitude(1) = std::complex<double>(0, -a);
                                return s;
                              }()});
  EXPECT_NEAR(m.alternatingVonMises, a * std::sqrt(1.5), 1e-9 * a);
  EXPECT_NEAR(m.alternatingPrincipal, a, 1e-9 * a);
}

TEST(StressCycle, PureShearAndASecondHarmonic) {
  const double tau = 30;
  const auto shear = measureCycle(Voigt::Zero(), {harmonic(1, 5, tau)});
  EXPECT_NEAR(shear.alternatingVonMises, std::sqrt(3.0) * tau, 1e-9 * tau);
  EXPECT_NEAR(shear.alternatingPrincipal, tau, 1e-9 * tau);
  // s_xx = cos t + 0.5 cos 2t: largest |s| 1.5 at t = 0 (the minimum, -0.75 at cos t = -1/2, is smaller).
  const auto two = measureCycle(Voigt::Zero(), {harmonic(1, 0, 1.0), harmonic(2, 0, 0.5)});
  EXPECT_NEAR(two.alternatingVonMises, 1.5, 1e-9);
  EXPECT_NEAR(two.alternatingPrincipal, 1.5, 1e-9);
}

TEST(StressCycle, ACompressiveMeanIsSignedAndHarmonicZeroRefused) {
  Voigt mean = Voigt::Zero();
  mean(2) = -120;
  EXPECT_NEAR(measureCycle(mean, {}).meanVonMises, -120, 1e-12);
  EXPECT_THROW(measureCycle(mean, {harmonic(0, 0, 1.0)}), cyclone::InputError);
}
