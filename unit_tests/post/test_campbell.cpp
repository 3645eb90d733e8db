#include <gtest/gtest.h>

#include "cyclone/post/CampbellDiagram.hpp"

using namespace cyclone;

namespace {
// A single-copy harmonic with two modes whose shapes are unit vectors on given nodes.
cyclic::NodalDiameterModes twoModes(int nd, double f1, int node1, double f2, int node2) {
  cyclic::NodalDiameterModes hm;
  hm.nodalDiameter = nd;
  hm.copies = 1;
  hm.frequenciesHz = {f1, f2};
  cyclic::ModeShape first{cyclic::NodalField(4, {0, 0, 0}), {}}, second = first;
  first.real[node1][0] = 1;
  second.real[node2][0] = 1;
  hm.shapes.push_back(first);
  hm.shapes.push_back(second);
  return hm;
}
}  // namespace

TEST(Campbell, FoldingOfEngineOrders) {
  const std::pair<int, int> cases[] = {{1, 1}, {12, 12}, {13, 11}, {23, 1}, {24, 0}, {25, 1}, {35, 11}, {48, 0}};
  for (auto [eo, nd] : cases) EXPECT_EQ(post::foldEngineOrder(eo, 24), nd) << "EO " << eo;
  EXPECT_EQ(post::foldEngineOrder(4, 7), 3);
}

TEST(Campbell, TrackingFollowsShapesThroughACrossing) {
  // Family A (shape on node 0) rises and crosses family B (node 1): by order the
  // branches would swap; by shape they do not.
  std::vector<cyclic::SpeedModes> speeds = {
      {0, {twoModes(0, 100, 0, 150, 1)}}, {5000, {twoModes(0, 140, 1, 160, 0)}}, {10000, {twoModes(0, 140, 1, 200, 0)}}};
  const auto branches = post::trackFamilies(speeds);
  ASSERT_EQ(branches.size(), 2u);
  EXPECT_EQ(branches[0].freqHz, (std::vector<double>{100, 160, 200}));
  EXPECT_EQ(branches[1].freqHz, (std::vector<double>{150, 140, 140}));
  EXPECT_NEAR(branches[0].worstMac, 1.0, 1e-15);
}

TEST(Campbell, ResonanceAtTheCrossingOfALinearBranch) {
  // f = 100 + 0.01 rpm meets EO 3 (f = 0.05 rpm) at 2500 rpm, 125 Hz; EO 1 never.
  post::Branch b;
  b.nd = 3;
  b.family = 1;
  b.rpm = {0, 2000, 4000};
  b.freqHz = {100, 120, 140};
  const auto r = post::findResonances({b}, 24, {1, 3, 21, 27});
  ASSERT_EQ(r.size(), 3u);  // EO 3, 21 (folds to 3), 27 (folds to 3)
  EXPECT_EQ(r[0].engineOrder, 27);  // sorted by speed: the highest EO crosses first
  for (const auto& x : r) {
    EXPECT_EQ(x.nd, 3);
    const double exact = 100 / (x.engineOrder / 60.0 - 0.01);
    if (exact <= 4000) {
      EXPECT_NEAR(x.rpm, exact, 1e-9);
    }
  }
  EXPECT_NEAR(r.back().rpm, 2500, 1e-9);
  EXPECT_NEAR(r.back().freqHz, 125, 1e-9);
}
