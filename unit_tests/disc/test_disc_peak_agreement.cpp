// A followed peak against the value-list study's frequency curves (the peaks both have at
// one value) and whether its optimum sits at the range's end, on hand-made curves.
#include <gtest/gtest.h>

#include "cyclone/disc/DiscPeakFollowing.hpp"

using namespace cyclone;

namespace {

disc::DiscPeakFollowing followedAt(std::vector<double> values, std::vector<double> peaks) {
  disc::DiscPeakFollowing f;
  f.grid = values;
  for (std::size_t i = 0; i < values.size(); ++i) {
    continuation::FollowedPeak p;
    p.parameter = values[i], p.measure = peaks[i];
    f.curve.points.push_back(p);
  }
  return f;
}

continuation::KnownPeak curvePeak(double value, double peak) {
  continuation::KnownPeak known;
  known.parameter = value;
  known.peak.measure = peak;
  return known;
}

}  // namespace

// Followed 1.1 at 10 and 2.0 at 30 against the curves' 1.0 and 2.5: |1.1/1 - 1| = 0.1 and
// |2/2.5 - 1| = 0.2; the curve at 25 has no followed value and is not compared.
TEST(DiscPeakAgreement, LargestRelativeDifferenceAtSharedValues) {
  const auto f = followedAt({10, 20, 30}, {1.1, 1.5, 2.0});
  const auto agreement = f.agreementWith({curvePeak(10, 1.0), curvePeak(25, 9.0), curvePeak(30, 2.5)});
  EXPECT_EQ(agreement.compared, 2);
  EXPECT_NEAR(agreement.largestRelativeDifference, 0.2, 1e-15);
}

// A value equal to 1e-12 of itself, as the grid's are where a study's value is added.
TEST(DiscPeakAgreement, ValuesMatchWithinAMillionthOfAMillionth) {
  const auto f = followedAt({0.3}, {4.0});
  EXPECT_EQ(f.agreementWith({curvePeak(0.3 * (1 + 1e-13), 5.0)}).compared, 1);
  EXPECT_EQ(f.agreementWith({curvePeak(0.3 * (1 + 1e-9), 5.0)}).compared, 0);
}

// A curve without a peak (measure 0) says nothing about the followed one.
TEST(DiscPeakAgreement, CurvesWithoutAPeakAreSkipped) {
  const auto f = followedAt({1, 2}, {1.0, 1.0});
  const auto agreement = f.agreementWith({curvePeak(1, 0.0), curvePeak(2, 0.0)});
  EXPECT_EQ(agreement.compared, 0);
  EXPECT_EQ(agreement.largestRelativeDifference, 0.0);
}

TEST(DiscPeakFollowingOptimum, AtTheGridsEndsOrInside) {
  auto f = followedAt({1, 2, 3}, {3.0, 1.0, 2.0});
  EXPECT_FALSE(f.optimumAtRangeEnd());  // no optimum chosen
  f.curve.optimum = 1;
  EXPECT_FALSE(f.optimumAtRangeEnd());
  f.curve.optimum = 0;
  EXPECT_TRUE(f.optimumAtRangeEnd());
  f.curve.optimum = 2;
  EXPECT_TRUE(f.optimumAtRangeEnd());
}
