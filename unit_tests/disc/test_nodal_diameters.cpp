// The nodal diameters a disc curve's harmonics live on (h EO mod N, folded to 0..N/2),
// with those its harmonics check adds, counted by hand.
#include <gtest/gtest.h>

#include "cyclone/disc/DiscReducedModels.hpp"

using namespace cyclone;

// 24 sectors, engine order 5: harmonics 0..3 on ND 0, 5, 10, 15 -> 9; the check's
// harmonic 4 adds 20 -> 4.
TEST(NodalDiametersForCheckedCurve, TheCheckAddsOneHarmonicByDefault) {
  EXPECT_EQ(disc::nodalDiametersForCheckedCurve(24, 5, {0, 1, 2, 3}, 0), (std::vector<int>{0, 4, 5, 9, 10}));
  EXPECT_EQ(disc::nodalDiametersFor(24, 5, {0, 1, 2, 3}), (std::vector<int>{0, 5, 9, 10}));
}

// Checked up to 6: harmonics 4, 5, 6 add 20 -> 4, 25 -> 1, 30 -> 6.
TEST(NodalDiametersForCheckedCurve, UpToTheCheckedHarmonic) {
  EXPECT_EQ(disc::nodalDiametersForCheckedCurve(24, 5, {0, 1, 2, 3}, 6), (std::vector<int>{0, 1, 4, 5, 6, 9, 10}));
}

// Harmonics given as a list (1 and 3 on 10 sectors, EO 2: ND 2 and 6 -> 4): the check
// starts above the highest, 4 (8 -> 2).
TEST(NodalDiametersForCheckedCurve, AListsCheckStartsAboveItsHighest) {
  EXPECT_EQ(disc::nodalDiametersForCheckedCurve(10, 2, {1, 3}, 0), (std::vector<int>{2, 4}));
}
