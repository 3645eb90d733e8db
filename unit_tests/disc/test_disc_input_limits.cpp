// The limits the disc's options are checked against before any work, at their edges: the
// time-domain check's periods and steps (disc::checkPeakInTimeOptions) and the reduced
// models' check frequencies (disc::checkModelCheckFrequencies); each refusal names its key.
#include <gtest/gtest.h>

#include <string>

#include "cyclone/core/Error.hpp"
#include "cyclone/disc/DiscPeakInTime.hpp"
#include "cyclone/disc/DiscReducedModels.hpp"

using namespace cyclone;

namespace {

// The key a refusal names, or "" where the options are taken.
std::string refusedKey(int periods, int stepsPerPeriod) {
  disc::PeakInTimeOptions o;
  o.maxPeriods = periods, o.stepsPerPeriod = stepsPerPeriod;
  try {
    disc::checkPeakInTimeOptions(o);
  } catch (const InputError& e) {
    return e.where();
  }
  return "";
}

}  // namespace

TEST(DiscInputLimits, TimeDomainCheckPeriodsAndSteps) {
  EXPECT_EQ(refusedKey(600, 1024), "");  // the defaults
  EXPECT_EQ(refusedKey(100, 16), "");
  EXPECT_EQ(refusedKey(99, 1024), "periods");
  EXPECT_EQ(refusedKey(600, 15), "steps_per_period");
  EXPECT_EQ(refusedKey(300, 65536), "");
  EXPECT_EQ(refusedKey(300, 65537), "steps_per_period");
  EXPECT_EQ(refusedKey(100, 1000000000), "steps_per_period");
  // periods x steps at most 2e7: the key whose value lies farther above its default named.
  EXPECT_EQ(refusedKey(20000, 1000), "");
  EXPECT_EQ(refusedKey(20001, 1000), "periods");
  EXPECT_EQ(refusedKey(2000000000, 1024), "periods");
  EXPECT_EQ(refusedKey(400, 65536), "steps_per_period");
}

TEST(DiscInputLimits, CheckFrequencies) {
  EXPECT_NO_THROW(disc::checkModelCheckFrequencies(0));
  EXPECT_NO_THROW(disc::checkModelCheckFrequencies(disc::kMaxCheckFrequencies));
  for (int bad : {-1, disc::kMaxCheckFrequencies + 1, 100000}) {
    try {
      disc::checkModelCheckFrequencies(bad);
      ADD_FAILURE() << bad << " taken";
    } catch (const InputError& e) {
      EXPECT_EQ(e.where(), "check_frequencies");
      EXPECT_NE(e.problem().find("must lie in 0..200"), std::string::npos) << e.problem();
    }
  }
}
