// HarmonicSet: coefficient layout follows the list; bad lists are input errors.
#include "cyclone/core/Error.hpp"
#include "cyclone/hbm/HarmonicSet.hpp"

#include <gtest/gtest.h>

using cyclone::InputError;
using cyclone::hbm::HarmonicSet;

TEST(HarmonicSet, UpToLaysOutMeanThenCosSinPairs) {
  const HarmonicSet set = HarmonicSet::upTo(3);
  EXPECT_EQ(set.size(), 4);
  EXPECT_EQ(set.numCoefficients(), 7);
  EXPECT_EQ(set.cosIndex(0), 0);
  EXPECT_EQ(set.cosIndex(1), 1);
  EXPECT_EQ(set.sinIndex(1), 2);
  EXPECT_EQ(set.cosIndex(3), 5);
  EXPECT_EQ(set.sinIndex(3), 6);
  EXPECT_EQ(set.minimumSamples(), 7);
}

TEST(HarmonicSet, OddHasNoMean) {
  const HarmonicSet set = HarmonicSet::odd(6);
  EXPECT_EQ(set.harmonics(), (std::vector<int>{1, 3, 5}));
  EXPECT_EQ(set.numCoefficients(), 6);
  EXPECT_FALSE(set.contains(0));
  EXPECT_FALSE(set.contains(2));
  EXPECT_EQ(set.cosIndex(5), 4);
  EXPECT_EQ(set.minimumSamples(), 11);
  EXPECT_THROW(set.cosIndex(0), InputError);
  EXPECT_THROW(HarmonicSet::odd(0), InputError);
}

TEST(HarmonicSet, AnyOrderFollowsTheList) {
  const HarmonicSet set({4, 0, 2});
  EXPECT_EQ(set.cosIndex(4), 0);
  EXPECT_EQ(set.sinIndex(4), 1);
  EXPECT_EQ(set.cosIndex(0), 2);
  EXPECT_EQ(set.cosIndex(2), 3);
  EXPECT_EQ(set.sinIndex(2), 4);
  EXPECT_EQ(set.maxHarmonic(), 4);
  EXPECT_EQ(set.minimumSamples(), 9);
}

TEST(HarmonicSet, RejectsBadLists) {
  EXPECT_THROW(HarmonicSet({}), InputError);
  EXPECT_THROW(HarmonicSet({1, -2}), InputError);
  EXPECT_THROW(HarmonicSet({1, 3, 1}), InputError);
  EXPECT_THROW(HarmonicSet::upTo(-1), InputError);
  EXPECT_THROW(HarmonicSet({0, 1}).sinIndex(0), InputError);
}
