// Tributary areas of a surface node set against closed forms on a structured box:
// the face's area for every element type, and per node on a hex8 and a hex20 grid (a
// cell's area A: a hex8 corner carries A / 4 of each cell it touches; a hex20 face's
// corners A / 24, its midside nodes 5 A / 24, from the split into straight triangles).
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "BoxMesh.hpp"
#include "cyclone/core/Error.hpp"
#include "cyclone/mesh/TributaryArea.hpp"

using namespace cyclone;
using mesh::ElementType;

TEST(TributaryArea, EveryElementTypeCoversTheFace) {
  for (ElementType type : {ElementType::Tet4, ElementType::Tet10, ElementType::Hex8, ElementType::Hex20}) {
    const auto box = test_support::makeBoxMesh(2.0, 3.0, 5.0, 2, 3, 4, type);
    const auto t = mesh::tributaryAreas(box, box.nodeSet("x1"), "x1");
    EXPECT_NEAR(t.total, 15.0, 1e-12) << mesh::exodusName(type);
    for (double a : t.area) EXPECT_GT(a, 0.0);
  }
}

TEST(TributaryArea, StructuredGridsMatchTheClosedForm) {
  constexpr double ly = 3.0, lz = 5.0;
  constexpr int ny = 3, nz = 4;
  const double cell = (ly / ny) * (lz / nz);
  for (ElementType type : {ElementType::Hex8, ElementType::Hex20}) {
    const auto box = test_support::makeBoxMesh(2.0, ly, lz, 2, ny, nz, type);
    const auto& nodes = box.nodeSet("x1");
    const auto t = mesh::tributaryAreas(box, nodes, "x1");
    EXPECT_EQ(t.faces, ny * nz);
    const double hy = ly / ny, hz = lz / nz;
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      const auto& p = box.coords[nodes[i]];
      // Which cells the node touches and where it sits in them: at a corner of the grid
      // of cells, or halfway along a cell edge (hex20's midside nodes).
      const double gy = p[1] / hy, gz = p[2] / hz;
      const bool cornerY = std::abs(gy - std::round(gy)) < 1e-9, cornerZ = std::abs(gz - std::round(gz)) < 1e-9;
      const int cellsY = cornerY ? ((std::round(gy) == 0 || std::round(gy) == ny) ? 1 : 2) : 1;
      const int cellsZ = cornerZ ? ((std::round(gz) == 0 || std::round(gz) == nz) ? 1 : 2) : 1;
      double expected;
      if (type == ElementType::Hex8) expected = cellsY * cellsZ * cell / 4;
      else if (cornerY && cornerZ) expected = cellsY * cellsZ * cell / 24;
      else expected = cellsY * cellsZ * 5 * cell / 24;
      EXPECT_NEAR(t.area[i], expected, 1e-12) << mesh::exodusName(type) << " node at (" << p[1] << ", " << p[2] << ")";
    }
  }
}

TEST(TributaryArea, NodesOnNoFaceAreRefused) {
  const auto box = test_support::makeBoxMesh(1.0, 1.0, 1.0, 2, 2, 2, ElementType::Hex8);
  // An edge line of the x1 face: nodes with y = 0 only.
  std::vector<mesh::Index> line;
  for (auto n : box.nodeSet("x1"))
    if (box.coords[n][1] == 0.0) line.push_back(n);
  try {
    mesh::tributaryAreas(box, line, "contact line");
    ADD_FAILURE() << "a line of nodes was given an area";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "contact line");
    EXPECT_NE(e.problem().find("carry no area"), std::string::npos) << e.what();
  }
}
