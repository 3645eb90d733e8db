// The fatigue map's node order for the table of every node, worst first: by safety
// factor, ties in node order, on a hand-made map.
#include <gtest/gtest.h>

#include "cyclone/fatigue/SectorVibration.hpp"

using cyclone::fatigue::FatigueMap;

TEST(FatigueMap, NodesWorstFirstSortsBySafetyFactorKeepingTiesInNodeOrder) {
  FatigueMap map;
  map.safetyFactor = {3.0, 1.5, 2.0, 1.5, 9.0};
  map.cycle.resize(map.safetyFactor.size());
  const std::vector<std::size_t> expected{1, 3, 2, 0, 4};
  EXPECT_EQ(map.nodesWorstFirst(), expected);
}

TEST(FatigueMap, NodesWorstFirstOfNoNodesIsEmpty) { EXPECT_TRUE(FatigueMap{}.nodesWorstFirst().empty()); }
