// The Mesh container, element type tables and the structural and geometric checks.
#include <gtest/gtest.h>

#include "MeshTestSupport.hpp"
#include "cyclone/mesh/ElementType.hpp"
#include "cyclone/mesh/Mesh.hpp"
#include "cyclone/mesh/MeshGeometryCheck.hpp"
#include "cyclone/mesh/ReferenceElement.hpp"

using namespace cyclone::mesh;
using cyclone::mesh::testing::expectInputError;

namespace {

// Two unit tets sharing face (0,1,2): apexes at z = +1 and z = -1.
Mesh twoTets() {
  Mesh mesh;
  mesh.source = "deck.inp";
  mesh.coords = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0, -1}};
  mesh.nodeIds = {1, 2, 3, 4, 5};
  ElementBlock up, down;
  up.name = "UP";
  up.id = 1;
  up.type = ElementType::Tet4;
  up.connectivity = {0, 1, 2, 3};
  up.elementIds = {7};
  down.name = "EALL";
  down.id = 2;
  down.type = ElementType::Tet4;
  down.connectivity = {0, 2, 1, 4};
  down.elementIds = {8};
  mesh.blocks = {up, down};
  mesh.nodeSets["base"] = {0, 1, 2};
  mesh.elementSets["all"] = {0, 1};
  mesh.sideSets["bottom"] = {{1, 3}};
  return mesh;
}

TEST(ElementType, Tables) {
  EXPECT_EQ(nodesPerElement(ElementType::Tet4), 4);
  EXPECT_EQ(nodesPerElement(ElementType::Tet10), 10);
  EXPECT_EQ(nodesPerElement(ElementType::Hex8), 8);
  EXPECT_EQ(nodesPerElement(ElementType::Hex20), 20);
  EXPECT_EQ(facesPerElement(ElementType::Tet10), 4);
  EXPECT_EQ(facesPerElement(ElementType::Hex20), 6);
  for (ElementType t : {ElementType::Tet4, ElementType::Tet10, ElementType::Hex8, ElementType::Hex20})
    EXPECT_EQ(elementTypeFromExodusName(exodusName(t), "x"), t);
  EXPECT_EQ(elementTypeFromExodusName("tetra", "x"), ElementType::Tet4);
  EXPECT_EQ(elementTypeFromExodusName("HEX  ", "x"), ElementType::Hex8);
  EXPECT_EQ(elementTypeFromExodusName("Tet10", "x"), ElementType::Tet10);
  expectInputError([] { elementTypeFromExodusName("HEX27", "model.exo: block 2"); },
                   {"model.exo: block 2", "unsupported element type 'HEX27'"});
  expectInputError([] { elementTypeFromExodusName("WEDGE6", "w.exo"); }, {"w.exo", "WEDGE6"});
}

// Each face's corners, in the given order, have a normal pointing away from the element's centre.
TEST(ElementType, FaceCornersPointOutwards) {
  for (ElementType t : {ElementType::Tet4, ElementType::Hex8}) {
    const auto X = referenceNodes(t);
    const Eigen::Vector3d centre = X.colwise().mean().transpose();
    for (int f = 0; f < facesPerElement(t); ++f) {
      const auto corners = faceCornerNodes(t, f);
      ASSERT_EQ(corners.size(), t == ElementType::Tet4 ? 3u : 4u);
      const Eigen::Vector3d a = X.row(corners[0]).transpose(), b = X.row(corners[1]).transpose(),
                            c = X.row(corners[2]).transpose();
      const Eigen::Vector3d normal = (b - a).cross(c - a);
      EXPECT_GT(normal.dot(a - centre), 0) << "type " << exodusName(t) << " face " << f;
    }
  }
  EXPECT_EQ(faceCornerNodes(ElementType::Hex20, 4), (std::vector<int>{0, 3, 2, 1}));  // Exodus side 5: z = -1
  EXPECT_EQ(faceCornerNodes(ElementType::Tet10, 0), (std::vector<int>{0, 1, 3}));
}

TEST(Mesh, CountsLookupsAndDefaultIds) {
  Mesh mesh = twoTets();
  EXPECT_EQ(mesh.numNodes(), 5);
  EXPECT_EQ(mesh.numElements(), 2);
  EXPECT_EQ(mesh.locateElement(1), (std::pair<int, Index>{1, 0}));
  expectInputError([&] { mesh.locateElement(2); }, {"deck.inp", "element index 2 out of range"});
  EXPECT_EQ(mesh.blocks[1].element(0)[3], 4);
  EXPECT_EQ(mesh.blocks[1].describeElement(0), "element 8 (block 'EALL')");
  EXPECT_EQ(mesh.nodeSet("base").size(), 3u);
  expectInputError([&] { mesh.nodeSet("fix"); }, {"deck.inp", "node set 'fix' does not exist", "'base'"});

  mesh.nodeIds.clear();
  mesh.blocks[1].elementIds.clear();
  mesh.assignDefaultIds();
  EXPECT_EQ(mesh.nodeIds, (std::vector<Index>{1, 2, 3, 4, 5}));
  EXPECT_EQ(mesh.blocks[0].elementIds, (std::vector<Index>{7}));
  EXPECT_EQ(mesh.blocks[1].elementIds, (std::vector<Index>{8}));  // after the largest id in use
  EXPECT_NO_THROW(checkConsistency(mesh));
}

TEST(Mesh, ConsistencyErrorsNameTheEntity) {
  EXPECT_NO_THROW(checkConsistency(twoTets()));
  {
    Mesh m = twoTets();
    m.blocks[1].connectivity[3] = 99;
    expectInputError([&] { checkConsistency(m); },
                     {"deck.inp: element 8 (block 'EALL') refers to node index 99 out of range"});
  }
  {
    Mesh m = twoTets();
    m.nodeIds[4] = 2;
    expectInputError([&] { checkConsistency(m); }, {"deck.inp", "node id 2 is used twice"});
  }
  {
    Mesh m = twoTets();
    m.blocks[1].elementIds[0] = 7;
    expectInputError([&] { checkConsistency(m); }, {"deck.inp", "element 7 (block 'EALL')", "block 'UP'"});
  }
  {
    Mesh m = twoTets();
    m.blocks[1].id = 1;
    expectInputError([&] { checkConsistency(m); }, {"deck.inp", "block 'EALL'", "block id 1"});
  }
  {
    Mesh m = twoTets();
    m.nodeSets["empty"] = {};
    expectInputError([&] { checkConsistency(m); }, {"deck.inp", "node set 'empty' is empty"});
  }
  {
    Mesh m = twoTets();
    m.elementSets["all"].push_back(2);
    expectInputError([&] { checkConsistency(m); }, {"deck.inp", "element set 'all'", "index 2 out of range"});
  }
  {
    Mesh m = twoTets();
    m.sideSets["bottom"][0].side = 4;
    expectInputError([&] { checkConsistency(m); }, {"deck.inp", "side set 'bottom'", "face 5", "element 8"});
  }
  {
    Mesh m = twoTets();
    m.blocks[0].connectivity.pop_back();
    expectInputError([&] { checkConsistency(m); }, {"deck.inp", "block 'UP'", "not a multiple of 4"});
  }
}

TEST(MeshGeometryCheck, InvertedAndDegenerateElements) {
  EXPECT_NO_THROW(checkElementGeometry(twoTets()));
  Mesh inverted = twoTets();
  std::swap(inverted.blocks[1].connectivity[1], inverted.blocks[1].connectivity[2]);
  expectInputError([&] { checkElementGeometry(inverted); },
                   {"deck.inp", "element 8 (block 'EALL')", "inverted or degenerate", "-1", "nodes 1 2 3 5"});
  Mesh flat = twoTets();
  flat.coords[4] = {0.3, 0.3, 0};  // apex in the base plane
  expectInputError([&] { checkElementGeometry(flat); }, {"element 8 (block 'EALL')", "inverted or degenerate"});
  Mesh tiny = twoTets();  // small but sound elements are fine: the test is scale-free
  for (auto& x : tiny.coords)
    for (auto& c : x) c *= 1e-6;
  EXPECT_NO_THROW(checkElementGeometry(tiny));
  expectInputError([&] { checkElementGeometry(inverted, [](int b, Index e) {
                     return "line of block " + std::to_string(b) + " element " + std::to_string(e);
                   }); },
                   {"line of block 1 element 0"});
}

}  // namespace

// The bounding box's diagonal: of a box 3 x 4 x 12 (13, the closed form), whatever the
// nodes inside it; 0 without nodes.
TEST(Mesh, BoundingDiagonalIsTheBoxDiagonal) {
  cyclone::mesh::Mesh m;
  EXPECT_EQ(cyclone::mesh::boundingDiagonal(m), 0.0);
  m.coords = {{1, -2, 5}, {4, 2, -7}, {2, 0, 0}};
  EXPECT_DOUBLE_EQ(cyclone::mesh::boundingDiagonal(m), 13.0);
}
