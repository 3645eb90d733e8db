// The headline's stability at the peak (DiscHeadline::stability): Hill's verdict at the
// traced curve's largest point, carried as a type and stated in the line, only where that
// point is the headline's peak. Hand-made curve results: what is tested is the reading of
// a verdict, not the verdict (Hill's method is verified in unit_tests/hbm).
#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "cyclone/disc/DiscForcedResponse.hpp"

using namespace cyclone;
using PS = disc::DiscHeadline::PeakStability;

namespace {

// A curve of three points whose middle one is the largest, at `curveHz`, with the
// verdict `stable` and leading exponent `exponent` there; the headline's peak at 1555 Hz
// with harmonics 0..5, converged (H 4 -> 5 changed it by 0.5 %).
response::ForcedResponseResult curveWith(int stable, std::complex<double> exponent, double curveHz = 1555.2,
                                         bool computed = true) {
  response::ForcedResponseResult r;
  r.omega = {2 * M_PI * 1500, 2 * M_PI * curveHz, 2 * M_PI * 1600};
  r.measure = {0.1, 0.26, 0.1};
  r.stable = {1, stable, 1};
  r.leadingExponent = {std::complex<double>(-30, 3000), exponent, std::complex<double>(-30, 3000)};
  r.stabilityComputed = computed;
  r.peakIndex = 1, r.peak = 0.26, r.peakOmega = r.omega[1];
  auto& best = r.harmonicsCheck.converged;
  best.found = true, best.maxHarmonic = 5, best.value = 0.2644, best.hz = 1555.0;
  best.belowHarmonic = 4, best.change = 0.005;
  return r;
}

}  // namespace

TEST(DiscHeadline, StatesHillsVerdictAtThePeak) {
  const auto stable = disc::discHeadline(curveWith(1, {-8.2, 3381.9}));
  EXPECT_EQ(stable.convergence, disc::DiscHeadline::Convergence::Converged);
  EXPECT_EQ(stable.stability, PS::Stable);
  EXPECT_NE(stable.text.find("stable by Hill's method at the traced curve's top"), std::string::npos) << stable.text;

  // The hammering shroud's resonance: a complex pair, the amplitude modulated.
  const auto torus = disc::discHeadline(curveWith(0, {529, 2730}));
  EXPECT_EQ(torus.stability, PS::UnstableComplex);
  EXPECT_DOUBLE_EQ(torus.leadingExponent.real(), 529);
  EXPECT_NE(torus.text.find("complex pair"), std::string::npos) << torus.text;
  EXPECT_NE(torus.text.find("does not settle"), std::string::npos) << torus.text;

  // A fold's middle branch: one real exponent.
  const auto fold = disc::discHeadline(curveWith(0, {68.5, 0}));
  EXPECT_EQ(fold.stability, PS::UnstableReal);
  EXPECT_NE(fold.text.find("a real Floquet exponent"), std::string::npos) << fold.text;

  const auto unsure = disc::discHeadline(curveWith(2, {1.7, 0}));
  EXPECT_EQ(unsure.stability, PS::Undetermined);
  EXPECT_NE(unsure.text.find("undetermined"), std::string::npos) << unsure.text;
}

// The convergence state a calling program branches on: converged where the last raise of
// H changed the peak by at most 1 % (0.5 % here), an estimate above (3 %) or where a level
// above was tried and not found, not found where the check found no peak.
TEST(DiscHeadline, ItsConvergenceIsTyped) {
  using C = disc::DiscHeadline::Convergence;
  EXPECT_EQ(disc::discHeadline(curveWith(1, {-8.2, 3381.9})).convergence, C::Converged);
  auto coarse = curveWith(1, {-8.2, 3381.9});
  coarse.harmonicsCheck.converged.change = 0.03;
  const auto estimate = disc::discHeadline(coarse);
  EXPECT_EQ(estimate.convergence, C::Estimate);
  EXPECT_STREQ(disc::convergenceName(estimate.convergence), "estimate");
  auto wall = curveWith(1, {-8.2, 3381.9});
  wall.harmonicsCheck.converged.notFoundHarmonic = 6;
  EXPECT_EQ(disc::discHeadline(wall).convergence, C::Estimate);
  auto none = curveWith(1, {-8.2, 3381.9});
  none.harmonicsCheck.converged.found = false;
  EXPECT_EQ(disc::discHeadline(none).convergence, C::NotFound);
  EXPECT_FALSE(disc::discHeadline(none).found());
}

TEST(DiscHeadline, SaysNothingOfAnotherPointsStability) {
  // The curve's top 3 % away from the headline's peak (another resonance, or the peak of
  // a lower harmonic count): its verdict is not the peak's.
  const auto elsewhere = disc::discHeadline(curveWith(0, {529, 2730}, 1600.0));
  EXPECT_EQ(elsewhere.stability, PS::NotComputed);
  EXPECT_EQ(elsewhere.text.find("Hill"), std::string::npos) << elsewhere.text;
  const auto notComputed = disc::discHeadline(curveWith(-1, {0, 0}, 1555.2, false));
  EXPECT_EQ(notComputed.stability, PS::NotComputed);
  EXPECT_EQ(notComputed.text.find("Hill"), std::string::npos) << notComputed.text;
}
