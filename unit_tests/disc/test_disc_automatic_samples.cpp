// The disc's automatic samples per period against the rule counted by hand: the friction
// contacts' 256, or the power of two from 8 (2 H + 1) where that is more.
#include <gtest/gtest.h>

#include "cyclone/disc/DiscHarmonicBalance.hpp"
#include "cyclone/hbm/HarmonicSet.hpp"

using namespace cyclone;

TEST(DiscAutomaticSamples, FrictionsCountUpToHFifteen) {
  EXPECT_EQ(disc::discAutomaticSamples(hbm::HarmonicSet::upTo(1)), 256);
  EXPECT_EQ(disc::discAutomaticSamples(hbm::HarmonicSet::upTo(15)), 256);  // 8 x 31 = 248
  EXPECT_EQ(disc::discAutomaticSamples(hbm::HarmonicSet({0, 1, 3})), 256);
}

TEST(DiscAutomaticSamples, ThenGrowsWithTheHighestHarmonic) {
  EXPECT_EQ(disc::discAutomaticSamples(hbm::HarmonicSet::upTo(16)), 512);   // 8 x 33 = 264
  EXPECT_EQ(disc::discAutomaticSamples(hbm::HarmonicSet::upTo(40)), 1024);  // 8 x 81 = 648
  EXPECT_EQ(disc::discAutomaticSamples(hbm::HarmonicSet({1, 20})), 512);    // 8 x 41 = 328
}
