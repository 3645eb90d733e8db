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

// Means come after the sets' nodes, in x, y, z; a DOF reads its nodes by their weights.
TEST(RomRetainedDofs, MeansFollowTheNodesAndReadTheirWeights) {
  const mesh::Mesh mesh = fourNodes();
  const auto dofs = rom::retainedDofs(mesh, {"contact"}, {}, {{"patch", {0, 3}, {0.25, 0.75}}});
  ASSERT_EQ(dofs.size(), 6);
  EXPECT_EQ(dofs.mean(2), nullptr);
  ASSERT_NE(dofs.mean(3), nullptr);
  EXPECT_EQ(dofs.mean(3)->name, "patch");
  for (int d = 0; d < 3; ++d) {
    EXPECT_EQ(dofs.dofs[std::size_t(3 + d)], std::make_pair(1, d));
    EXPECT_EQ(dofs.axis(3 + d), Eigen::Vector3d::Unit(d));
  }
  std::vector<Eigen::Vector3d> u(4, Eigen::Vector3d::Zero());
  u[0] = {4, 8, 12}, u[2] = {1, 2, 3}, u[3] = {-4, 0, 4};
  EXPECT_DOUBLE_EQ(dofs.read(1, u), 2.0);                       // node 2's y
  EXPECT_DOUBLE_EQ(dofs.read(5, u), 0.25 * 12 + 0.75 * 4);      // the mean's z
  EXPECT_EQ(rom::retainedDofs(mesh, {}, {}, {{"alone", {1}, {1.0}}}).size(), 3);  // means without sets
  const auto where = [&](rom::RetainedMean m) {
    try {
      rom::retainedDofs(mesh, {"contact"}, {}, {m});
    } catch (const InputError& e) {
      return e.where();
    }
    return std::string("(no error)");
  };
  EXPECT_EQ(where({"p", {}, {}}), "retained/means/p");
  EXPECT_EQ(where({"p", {0, 1}, {1.0}}), "retained/means/p");
  EXPECT_EQ(where({"p", {0, 0}, {1.0, 1.0}}), "retained/means/p");
  EXPECT_EQ(where({"p", {0, 9}, {1.0, 1.0}}), "retained/means/p");
  EXPECT_EQ(where({"p", {0, 1}, {1.0, NAN}}), "retained/means/p");
  EXPECT_EQ(where({"", {0}, {0.0}}), "retained/means/0");
}
