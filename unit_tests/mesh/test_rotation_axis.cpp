// The geometry of a rotation axis against a mesh: the outermost radius and whether two
// axes are one line, on points whose distances are known by hand.
#include <gtest/gtest.h>

#include <cmath>

#include "cyclone/mesh/Mesh.hpp"
#include "cyclone/mesh/RotatedNodePairing.hpp"

using namespace cyclone::mesh;

namespace {

Mesh points(std::vector<Point> coords) {
  Mesh mesh;
  mesh.coords = std::move(coords);
  return mesh;
}

}  // namespace

// About the z axis a node's radius is hypot(x, y), whatever its z.
TEST(OutermostRadius, IsTheLargestDistanceFromTheZAxis) {
  const Mesh mesh = points({{1, 0, 5}, {3, 4, -2}, {0, 2, 100}});
  EXPECT_DOUBLE_EQ(outermostRadius(mesh, RotationAxis{}), 5.0);  // 3-4-5
}

// An axis along x through (0, 1, 0): node (7, 1, 3) lies 3 from it, (0, -1, 0) lies 2.
TEST(OutermostRadius, TakesTheAxisPointAndDirection) {
  const Mesh mesh = points({{7, 1, 3}, {0, -1, 0}});
  RotationAxis axis;
  axis.point = Eigen::Vector3d(0, 1, 0);
  axis.direction = Eigen::Vector3d(2, 0, 0);  // not of unit length: normalised
  EXPECT_DOUBLE_EQ(outermostRadius(mesh, axis), 3.0);
}

TEST(OutermostRadius, IsZeroWithoutNodes) { EXPECT_EQ(outermostRadius(Mesh{}, RotationAxis{}), 0.0); }

TEST(SameRotationLine, HoldsForEitherSenseAndAnyPointOnTheLine) {
  RotationAxis a, b;
  b.direction = Eigen::Vector3d(0, 0, -3);
  b.point = Eigen::Vector3d(0, 0, 42);
  EXPECT_TRUE(sameRotationLine(a, b));
  EXPECT_TRUE(sameRotationLine(b, a));
}

TEST(SameRotationLine, FailsForAParallelLineOrATiltedOne) {
  RotationAxis a, shifted, tilted;
  shifted.point = Eigen::Vector3d(1e-3, 0, 0);  // parallel, a thousandth away
  tilted.direction = Eigen::Vector3d(1e-6, 0, 1);  // through the same point, a microradian off
  EXPECT_FALSE(sameRotationLine(a, shifted));
  EXPECT_FALSE(sameRotationLine(a, tilted));
}
