// rom::retainedDofs: the order of the retained DOFs (sets merged in order, a node
// once, each node's directions in its set's order) that every compliance row
// follows, and the input checks. retainedDofs reads only node sets, so the mesh
// here holds points and node sets, no elements.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "cyclone/core/Error.hpp"
#include "cyclone/rom/RetainedDofs.hpp"

using namespace cyclone;

namespace {

mesh::Mesh fourNodes() {
  mesh::Mesh m;
  m.coords = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}};
  m.nodeIds = {10, 11, 12, 13};
  m.nodeSets["tip"] = {3, 1};
  m.nodeSets["root"] = {1, 0};
  m.nodeSets["contact"] = {2};
  m.source = "four points";
  return m;
}

// Rows: the normal of a face tilted by 30 degrees about z and its two tangents.
Eigen::Matrix3d tiltedFrame() {
  const double c = std::cos(M_PI / 6), s = std::sin(M_PI / 6);
  Eigen::Matrix3d R;
  R << c, s, 0, -s, c, 0, 0, 0, 1;
  return R;
}

std::string whereOf(const mesh::Mesh& mesh, const std::vector<std::string>& sets,
                    const std::map<std::string, rom::RetainedDirections>& directions) {
  try {
    rom::retainedDofs(mesh, sets, directions);
  } catch (const InputError& e) {
    return e.where();
  }
  return "(no error)";
}

}  // namespace

TEST(RomRetainedDofs, OrderFollowsSetsNodesAndDirections) {
  const mesh::Mesh mesh = fourNodes();
  rom::RetainedDirections contact;
  contact.directions = {0, 2};  // the normal, then the out-of-plane tangent
  contact.frame = tiltedFrame();
  const auto dofs = rom::retainedDofs(mesh, {"tip", "root", "contact"}, {{"contact", contact}});
  // Node 1 is in "tip" and "root" with the same (default) directions: kept once, where first met.
  ASSERT_EQ(dofs.nodes, (std::vector<mesh::Index>{3, 1, 0, 2}));
  EXPECT_EQ(dofs.rotated, (std::vector<bool>{false, false, false, true}));
  ASSERT_EQ(dofs.size(), 3 * 3 + 2);
  for (int node = 0; node < 3; ++node)
    for (int d = 0; d < 3; ++d) {
      EXPECT_EQ(dofs.dofs[std::size_t(3 * node + d)], std::make_pair(node, d));
      EXPECT_EQ(dofs.axis(3 * node + d), Eigen::Vector3d::Unit(d));
    }
  EXPECT_EQ(dofs.dofs[9], std::make_pair(3, 0));
  EXPECT_EQ(dofs.dofs[10], std::make_pair(3, 2));
  EXPECT_EQ(dofs.axis(9), tiltedFrame().row(0).transpose());
  EXPECT_EQ(dofs.axis(10), tiltedFrame().row(2).transpose());
}

TEST(RomRetainedDofs, BadInputIsNamed) {
  const mesh::Mesh mesh = fourNodes();
  const auto with = [](std::vector<int> directions, Eigen::Matrix3d frame = Eigen::Matrix3d::Identity()) {
    rom::RetainedDirections d;
    d.directions = std::move(directions);
    d.frame = frame;
    return d;
  };
  EXPECT_EQ(whereOf(mesh, {}, {}), "retained");
  EXPECT_EQ(whereOf(mesh, {"tip"}, {{"root", with({0})}}), "retained/root");  // a set not retained
  EXPECT_EQ(whereOf(mesh, {"tip"}, {{"tip", with({})}}), "retained/tip/directions");
  EXPECT_EQ(whereOf(mesh, {"tip"}, {{"tip", with({0, 0})}}), "retained/tip/directions");
  EXPECT_EQ(whereOf(mesh, {"tip"}, {{"tip", with({3})}}), "retained/tip/directions");
  Eigen::Matrix3d skew = tiltedFrame();
  skew(0, 0) += 1e-6;  // not orthonormal: T^T A T would be another quantity
  EXPECT_EQ(whereOf(mesh, {"tip"}, {{"tip", with({0}, skew)}}), "retained/tip/frame");
  // Node 1 retained by "tip" in x, y, z and by "root" only along x.
  EXPECT_EQ(whereOf(mesh, {"tip", "root"}, {{"root", with({0})}}), "retained/root");
  EXPECT_THROW(rom::retainedDofs(mesh, {"missing"}, {}), InputError);
}
