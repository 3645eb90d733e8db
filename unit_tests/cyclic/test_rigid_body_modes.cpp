// A nodal diameter's rigid-body modes: its frequencies below 1e-4 of the highest one
// computed, counted on hand-made lists.
#include <gtest/gtest.h>

#include "cyclone/cyclic/CyclicModalAnalysis.hpp"

using cyclone::cyclic::NodalDiameterModes;

namespace {

// The count for one nodal diameter whose solver returned `hz`.
int rigidBodyModesAmong(const std::vector<double>& hz) {
  NodalDiameterModes modes;
  modes.frequenciesHz = hz;
  return modes.rigidBodyModes();
}

}  // namespace

// An unheld sector at ND 0: six rigid-body modes at round-off, then the elastic ones.
TEST(RigidBodyModes, CountsTheFrequenciesAtRoundOff) {
  EXPECT_EQ(rigidBodyModesAmong({0, 1e-7, 2e-6, 3e-5, 4e-4, 5e-3, 120, 480, 1000}), 6);
}

// The threshold is 1e-4 of the highest: 0.099 Hz counts against 1000 Hz, 0.1 Hz does not.
TEST(RigidBodyModes, TheThresholdIsATenThousandthOfTheHighest) {
  EXPECT_EQ(rigidBodyModesAmong({0.099, 500, 1000}), 1);
  EXPECT_EQ(rigidBodyModesAmong({0.1, 500, 1000}), 0);
}

TEST(RigidBodyModes, NoneForAHeldSectorOrNoModes) {
  EXPECT_EQ(rigidBodyModesAmong({87.5, 312, 940}), 0);
  EXPECT_EQ(rigidBodyModesAmong({}), 0);
}
