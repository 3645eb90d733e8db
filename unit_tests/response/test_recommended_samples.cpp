// The default time samples per period of a matrix system's curve, against the rule
// counted by hand: max(64, 4 H + 1), and for a nonsmooth law also its own count and the
// power of two from 8 (2 H + 1).
#include <gtest/gtest.h>

#include <memory>

#include "cyclone/hbm/CubicSpring.hpp"
#include "cyclone/hbm/FrictionContact.hpp"
#include "cyclone/hbm/ScalarElementAdapter.hpp"
#include "cyclone/hbm/UnilateralSpring.hpp"
#include "cyclone/response/ForcedResponseChecks.hpp"

using namespace cyclone;

namespace {

std::shared_ptr<const hbm::NonlinearElement> cubic() {
  return std::make_shared<hbm::ScalarElementAdapter>(std::make_shared<hbm::CubicSpring>(1.0));
}
std::shared_ptr<const hbm::NonlinearElement> gap() {
  return std::make_shared<hbm::ScalarElementAdapter>(std::make_shared<hbm::UnilateralSpring>(1.0, 0.0));
}
std::shared_ptr<const hbm::NonlinearElement> friction() {
  hbm::FrictionContactParameters p;
  p.tangentialDirections = 2, p.kn = 1, p.kt = 1, p.mu = 0.3, p.preload = 1;
  return std::make_shared<hbm::FrictionContact>(p);
}

}  // namespace

// Smooth laws (none, or a cubic spring): 64 up to H = 15, then 4 H + 1 (H = 20: 81).
TEST(RecommendedSamples, SmoothSystemsTakeSixtyFourOrFourHPlusOne) {
  EXPECT_EQ(response::recommendedSamples(hbm::HarmonicSet::upTo(3), {}), 64);
  EXPECT_EQ(response::recommendedSamples(hbm::HarmonicSet::upTo(15), {cubic()}), 64);
  EXPECT_EQ(response::recommendedSamples(hbm::HarmonicSet::upTo(20), {cubic()}), 81);
}

// A gap (64 of its own) at H = 3: 8 x 7 = 56 -> 64; at H = 20: 8 x 41 = 328 -> 512.
TEST(RecommendedSamples, NonsmoothLawsGrowWithTheHarmonics) {
  EXPECT_EQ(response::recommendedSamples(hbm::HarmonicSet::upTo(3), {gap()}), 64);
  EXPECT_EQ(response::recommendedSamples(hbm::HarmonicSet::upTo(20), {cubic(), gap()}), 512);
}

// Friction's own 256 rules until 8 (2 H + 1) passes it: H = 10 (168 -> 256), H = 20 (512).
TEST(RecommendedSamples, FrictionTakesItsOwnCountFirst) {
  EXPECT_EQ(response::recommendedSamples(hbm::HarmonicSet::upTo(3), {friction()}), 256);
  EXPECT_EQ(response::recommendedSamples(hbm::HarmonicSet::upTo(10), {friction()}), 256);
  EXPECT_EQ(response::recommendedSamples(hbm::HarmonicSet::upTo(20), {friction()}), 512);
}
