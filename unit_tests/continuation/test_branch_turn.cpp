// The predictor-flip test of the continuation: a step back along the traced
// path is caught; a fold taken with a large step, a gentle bend and a step
// past the path's start are not.
#include <gtest/gtest.h>

#include <cmath>

#include "cyclone/continuation/BranchTurn.hpp"

using namespace cyclone::continuation;

namespace {

BranchPoint point(double p, double x) { return {p, Eigen::VectorXd::Constant(1, x)}; }

int retraced(const std::vector<BranchPoint>& path, const BranchPoint& c) {
  std::vector<const BranchPoint*> ptrs;
  for (const auto& q : path) ptrs.push_back(&q);
  return retracedFrom(ptrs, c);
}
bool turnsBack(const std::vector<BranchPoint>& path, const BranchPoint& c) { return retraced(path, c) >= 0; }

}  // namespace

TEST(BranchTurn, StepBackAlongThePathIsCaught) {
  // x = p^2 traced upwards, then a step back to between the last two points.
  std::vector<BranchPoint> path;
  for (double p : {0.0, 0.1, 0.2, 0.3}) path.push_back(point(p, p * p));
  EXPECT_TRUE(turnsBack(path, point(0.25, 0.0625)));
  EXPECT_TRUE(turnsBack(path, point(0.15, 0.0225)));  // two segments back
  EXPECT_FALSE(turnsBack(path, point(0.4, 0.16)));     // onward
}

TEST(BranchTurn, FoldTakenWithALargeStepIsNot) {
  // A hairpin: the path rises along x = 0 to p = 1, the fold's other half
  // returns at x = 0.5. A step onto that half turns back by 150 degrees but
  // lands half a unit from the path: a true fold.
  std::vector<BranchPoint> path{point(0.0, 0.0), point(0.5, 0.0), point(1.0, 0.0)};
  const BranchPoint otherHalf = point(0.1, 0.5);
  EXPECT_LT(turnCosine(path[1], path[2], otherHalf), -0.5);
  EXPECT_FALSE(turnsBack(path, otherHalf));
  // The same turn landing on the traced half: caught.
  EXPECT_TRUE(turnsBack(path, point(0.1, 0.02)));
}

TEST(BranchTurn, GentleBendAndTooShortPathsAreNot) {
  std::vector<BranchPoint> path{point(0, 0), point(1, 0)};
  EXPECT_FALSE(turnsBack(path, point(1.5, 0.5)));               // 45 degrees
  EXPECT_FALSE(turnsBack({point(0, 0)}, point(-1, 0)));           // nothing to go back along
  EXPECT_NEAR(turnCosine(point(0, 0), point(1, 0), point(0, 0)), -1.0, 1e-15);
}

// The flip spread over tiny steps (what LOCA did at a friction kink): the path
// creeps forward, turns around in small steps, then walks back over its old
// segments. Caught when it lands on them; the kink is the turning point.
TEST(BranchTurn, GradualTurnAroundIsCaughtAtItsTip) {
  std::vector<BranchPoint> path;
  for (double p : {0.0, 0.1, 0.2, 0.3, 0.4}) path.push_back(point(p, p));  // forward
  path.push_back(point(0.401, 0.4012));                                    // creeping
  path.push_back(point(0.4005, 0.4008));                                   // turned, tiny
  EXPECT_EQ(retraced(path, point(0.35, 0.35)), 5);  // back on the segment 0.3 -> 0.4: kink at index 5
  EXPECT_EQ(retraced(path, point(0.41, 0.43)), -1);
}

// A corrector that lands far from its predictor: the step is more than
// kJumpRatio times the one before it. LOCA's adaptive step grows by at most
// 1.5x, so a regular path never comes close.
TEST(BranchTurn, CorrectorJumpIsAStepFarLongerThanTheLast) {
  const auto a = point(0, 0), b = point(0.1, 0.0);
  EXPECT_FALSE(branchJump(a, b, point(0.25, 0.0)));    // 1.5x: LOCA's largest growth
  EXPECT_FALSE(branchJump(a, b, point(0.1, 0.45)));    // a sharp bend, 4.5x
  EXPECT_TRUE(branchJump(a, b, point(0.05, -0.6)));    // back and far off: another branch
  EXPECT_FALSE(branchJump(a, a, point(1, 1)));         // no step before: no measure
}

// A step that lands back on the path traced before, far behind along it, is a
// jump, moving either way; a step back about its own length behind (a retrace
// at a kink), continuing along the last segment, a fold's other half and a step
// off the path are not.
TEST(BranchTurn, LandingOnThePathFarBehindIsAJump) {
  std::vector<BranchPoint> path;
  for (int i = 0; i <= 10; ++i) path.push_back(point(0.1 * i, 0.0));       // p = 0 .. 1 at x = 0,
  for (int i = 1; i <= 10; ++i) path.push_back(point(1.0, 0.1 * i));       // x = 0 .. 1 at p = 1,
  for (int i = 1; i <= 5; ++i) path.push_back(point(1.0 - 0.1 * i, 1.0));  // p = 1 .. 0.5 at x = 1
  std::vector<const BranchPoint *> ptrs;
  for (const auto& q : path) ptrs.push_back(&q);
  // b = (0.5, 1); arclength back to (0.45, 0): 0.55 + 1 + 0.5 = 2.05 > 2 x 1.0
  // (the chord).
  EXPECT_TRUE(landsOnTracedPath(ptrs, point(0.45, 0.0)));
  EXPECT_TRUE(landsOnTracedPath(ptrs, point(0.3, 0.05)));   // near it (within a tenth of the step)
  EXPECT_FALSE(landsOnTracedPath(ptrs, point(0.75, 1.0)));  // back a step along the path: a retrace
  EXPECT_FALSE(landsOnTracedPath(ptrs, point(0.4, 1.0)));   // on along the last segment
  EXPECT_FALSE(landsOnTracedPath(ptrs, point(0.55, 0.9)));  // a fold's other half, a step off
  EXPECT_FALSE(landsOnTracedPath(ptrs, point(0.5, 0.5)));   // off the path
  EXPECT_FALSE(landsOnTracedPath(ptrs, point(0.9, 0.0)));   // on it but only 1.6 behind for a 1.08 chord
  // Creeping steps at a kink after regular steps of 0.1, to and fro: a step of
  // 6e-4 inside the cluster lands 1.6e-3 behind along it, more than two of its
  // own length but far less than two regular steps.
  for (double p : {0.499, 0.4995, 0.4992}) path.push_back(point(p, 1.0));
  ptrs.clear();
  for (const auto& q : path) ptrs.push_back(&q);
  EXPECT_FALSE(landsOnTracedPath(ptrs, point(0.4998, 1.0)));
}
