// What a followed peak's curve says about itself: its jumps and its largest peak, on
// hand-made points.
#include <gtest/gtest.h>

#include "cyclone/continuation/PeakFollowing.hpp"

using cyclone::continuation::FollowedPeak;
using cyclone::continuation::FollowedPeakCurve;

namespace {

FollowedPeakCurve curveOf(std::vector<double> measures, std::vector<bool> jumps) {
  FollowedPeakCurve curve;
  for (std::size_t i = 0; i < measures.size(); ++i) {
    FollowedPeak p;
    p.parameter = double(i + 1), p.measure = measures[i], p.jump = jumps[i];
    curve.points.push_back(p);
  }
  return curve;
}

}  // namespace

TEST(FollowedPeakCurve, CountsItsJumps) {
  EXPECT_EQ(curveOf({1, 2, 3, 4}, {false, true, false, true}).jumps(), 2);
  EXPECT_EQ(curveOf({1, 2}, {false, false}).jumps(), 0);
}

// The largest measure's index; of equal ones the first.
TEST(FollowedPeakCurve, LargestPeakIsTheFirstOfTheLargest) {
  EXPECT_EQ(curveOf({0.5, 2.5, 1.0, 2.5}, {false, false, false, false}).largestPeak(), 1u);
  EXPECT_EQ(curveOf({3.0, 2.0}, {false, false}).largestPeak(), 0u);
  EXPECT_EQ(FollowedPeakCurve{}.largestPeak(), 0u);
}
