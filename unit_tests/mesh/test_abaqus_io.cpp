// CalculiX/Abaqus decks: small decks written here, checked against hand-known
// coordinates, connectivity, set contents and volumes; every kind of bad input
// must name the file and line (or the element) and say what is wrong.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "MeshTestSupport.hpp"
#include "cyclone/mesh/AbaqusIO.hpp"

using namespace cyclone::mesh;
using cyclone::mesh::testing::expectInputError;
using cyclone::mesh::testing::maxMidEdgeOffset;
using cyclone::mesh::testing::meshVolume;
using cyclone::mesh::testing::TempDirectory;

namespace {

// Two unit cubes side by side along x: node (i,j,k) has id 1 + i + 3j + 6k, at (i, j, k).
const char* kTwoHexDeck = R"(** two C3D8 cubes
*HEADING
two cubes, with keywords Cyclone skips
*NODE, NSET=NALL
1, 0, 0, 0
2, 1, 0, 0
3, 2, 0, 0
4, 0, 1, 0
5, 1, 1, 0
6, 2, 1, 0
7, 0, 0, 1
8, 1, 0, 1
9, 2, 0, 1
10, 0, 1, 1
11, 1, 1, 1
12, 2, 1, 1
*ELEMENT, TYPE=C3D8R, ELSET=CUBES
1, 1, 2, 5, 4, 7, 8, 11, 10
2, 2, 3, 6, 5, 8, 9, 12, 11
*NSET, NSET=XMIN, GENERATE
1, 10, 3
*NSET, NSET=BOTH
XMIN, 3,
12
*ELSET, ELSET=ALL, GENERATE
1, 2
*ELSET, ELSET=SECOND
2
*MATERIAL, NAME=STEEL
*ELASTIC
210000., 0.3
*STEP
*STATIC
*BOUNDARY
XMIN, 1, 3
*END STEP
)";

TEST(AbaqusReader, TwoHexahedraWithGeneratedAndNestedSets) {
  TempDirectory dir;
  const Mesh mesh = readAbaqusInp(dir.write("cubes.inp", kTwoHexDeck));
  ASSERT_EQ(mesh.numNodes(), 12);
  ASSERT_EQ(mesh.blocks.size(), 1u);
  const auto& block = mesh.blocks[0];
  EXPECT_EQ(block.name, "CUBES");
  EXPECT_EQ(block.id, 1);
  EXPECT_EQ(block.type, ElementType::Hex8);
  ASSERT_EQ(block.numElements(), 2);
  EXPECT_EQ(block.elementIds, (std::vector<Index>{1, 2}));
  // Node (i,j,k) sits at (i,j,k).
  for (Index n = 0; n < 12; ++n) {
    const Index id = mesh.nodeIds[n] - 1;
    EXPECT_EQ(mesh.coords[n], (Point{double(id % 3), double((id / 3) % 2), double(id / 6)}));
  }
  // Second element's 7th node is id 12.
  EXPECT_EQ(mesh.nodeIds[block.element(1)[6]], 12);
  EXPECT_NEAR(meshVolume(mesh), 2.0, 1e-14);

  std::vector<Index> xmin;
  for (Index n : mesh.nodeSet("XMIN")) xmin.push_back(mesh.nodeIds[n]);
  EXPECT_EQ(xmin, (std::vector<Index>{1, 4, 7, 10}));
  for (Index n : mesh.nodeSet("XMIN")) EXPECT_EQ(mesh.coords[n][0], 0.0);
  std::vector<Index> both;
  for (Index n : mesh.nodeSet("BOTH")) both.push_back(mesh.nodeIds[n]);
  EXPECT_EQ(both, (std::vector<Index>{1, 4, 7, 10, 3, 12}));
  EXPECT_EQ(mesh.nodeSet("NALL").size(), 12u);
  EXPECT_EQ(mesh.elementSets.at("ALL"), (std::vector<Index>{0, 1}));
  EXPECT_EQ(mesh.elementSets.at("SECOND"), (std::vector<Index>{1}));
  EXPECT_EQ(mesh.elementSets.at("CUBES"), (std::vector<Index>{0, 1}));  // ELSET= on *ELEMENT defines it
  // Set names are case-sensitive.
  expectInputError([&] { mesh.nodeSet("xmin"); }, {"node set 'xmin' does not exist", "'XMIN'"});
}

TEST(AbaqusReader, Tet4AndTet10LowerCaseKeywordsAndVariants) {
  TempDirectory dir;
  const std::string path = dir.write("tets.inp", R"(*node
1, 0., 0., 0.
2, 1.0e0, 0., 0.
3, 0., 1.D0, 0.
4, 0., 0., 1.
5, 0.5, 0., 0.
6, 0.5, 0.5, 0.
7, 0., 0.5, 0.
8, 0., 0., 0.5
9, 0.5, 0., 0.5
10, 0., 0.5, 0.5
11, 2., 0., 0.
12, 3., 0., 0.
13, 2., 1., 0.
14, 2., 0., 1.
*Element, type=c3d10T, elset=Quadratic
1, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10
*ELEMENT, TYPE=C3D4
2, 11, 12, 13, 14
)");
  const Mesh mesh = readAbaqusInp(path);
  ASSERT_EQ(mesh.blocks.size(), 2u);
  EXPECT_EQ(mesh.blocks[0].name, "Quadratic");
  EXPECT_EQ(mesh.blocks[0].type, ElementType::Tet10);
  EXPECT_EQ(mesh.blocks[1].type, ElementType::Tet4);
  EXPECT_EQ(mesh.blocks[1].numElements(), 1);
  EXPECT_EQ(mesh.blocks[1].name, "C3D4");
  EXPECT_EQ(mesh.coords[2], (Point{0, 1, 0}));  // Fortran exponent 1.D0
  EXPECT_EQ(maxMidEdgeOffset(mesh), 0.0);
}

TEST(AbaqusReader, VariantNamesGroupByTypeAsWritten) {
  TempDirectory dir;
  const std::string path = dir.write("tets.inp", R"(*NODE
11, 2., 0., 0.
12, 3., 0., 0.
13, 2., 1., 0.
14, 2., 0., 1.
15, 2., 0., -1.
*ELEMENT, TYPE=C3D4
2, 11, 12, 13, 14
*ELEMENT, TYPE=C3D4H
3, 15, 12, 13, 11
*ELEMENT, TYPE=C3D4
4, 15, 12, 13, 14
)");
  // Without ELSET=, blocks are named by the type as written; C3D4 elements of two keywords share one.
  const Mesh mesh = readAbaqusInp(path);
  ASSERT_EQ(mesh.blocks.size(), 2u);
  EXPECT_EQ(mesh.blocks[0].name, "C3D4");
  EXPECT_EQ(mesh.blocks[0].elementIds, (std::vector<Index>{2, 4}));
  EXPECT_EQ(mesh.blocks[1].name, "C3D4H");
  EXPECT_EQ(mesh.blocks[1].elementIds, (std::vector<Index>{3}));
  EXPECT_EQ(mesh.blocks[1].type, ElementType::Tet4);
}

TEST(AbaqusReader, Hex20OnContinuationLines) {
  TempDirectory dir;
  // Brick [0,2]x[0,1]x[0,1]; mid-edge nodes in Exodus/Abaqus order 01,12,23,30,45,56,67,74,04,15,26,37.
  const std::string path = dir.write("brick.inp", R"(*NODE
1, 0, 0, 0
2, 2, 0, 0
3, 2, 1, 0
4, 0, 1, 0
5, 0, 0, 1
6, 2, 0, 1
7, 2, 1, 1
8, 0, 1, 1
9, 1, 0, 0
10, 2, 0.5, 0
11, 1, 1, 0
12, 0, 0.5, 0
13, 1, 0, 1
14, 2, 0.5, 1
15, 1, 1, 1
16, 0, 0.5, 1
17, 0, 0, 0.5
18, 2, 0, 0.5
19, 2, 1, 0.5
20, 0, 1, 0.5
*ELEMENT, TYPE=C3D20R, ELSET=BRICK
7, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15,
16, 17, 18, 19, 20
)");
  const Mesh mesh = readAbaqusInp(path);
  ASSERT_EQ(mesh.blocks.size(), 1u);
  EXPECT_EQ(mesh.blocks[0].type, ElementType::Hex20);
  EXPECT_EQ(mesh.blocks[0].elementIds, (std::vector<Index>{7}));
  for (int a = 0; a < 20; ++a) EXPECT_EQ(mesh.nodeIds[mesh.blocks[0].element(0)[a]], a + 1);
  EXPECT_NEAR(meshVolume(mesh), 2.0, 1e-14);
  EXPECT_EQ(maxMidEdgeOffset(mesh), 0.0);
}

TEST(AbaqusReader, IncludesAreRelativeToTheIncludingFile) {
  TempDirectory dir;
  dir.write("parts/nodes.inp", "*NODE, NSET=NALL\n1, 0, 0, 0\n2, 1, 0, 0\n*INCLUDE, INPUT=more_nodes.inp\n");
  dir.write("parts/more_nodes.inp", "** data lines continuing the including file's *NODE\n3, 0, 1, 0\n4, 0, 0, 1\n");
  const std::string path = dir.write("main.inp",
                                     "*HEADING\ninclude test\n*Include, input=parts/nodes.inp\n"
                                     "*ELEMENT, TYPE=C3D4, ELSET=E1\n1, 1, 2, 3, 4\n");
  const Mesh mesh = readAbaqusInp(path);
  EXPECT_EQ(mesh.numNodes(), 4);
  EXPECT_EQ(mesh.nodeSet("NALL").size(), 4u);
  EXPECT_EQ(mesh.coords[3], (Point{0, 0, 1}));
  EXPECT_NEAR(meshVolume(mesh), 1.0 / 6.0, 1e-15);
  EXPECT_EQ(mesh.source, path);

  // An error inside an included file names that file and its line.
  dir.write("parts/more_nodes.inp", "3, 0, 1, 0\n4, 0, zero, 1\n");
  expectInputError([&] { readAbaqusInp(path); }, {"more_nodes.inp:2", "bad number 'zero'"});
  dir.write("parts/nodes.inp", "*NODE\n*INCLUDE, INPUT=missing.inp\n");
  expectInputError([&] { readAbaqusInp(path); }, {"nodes.inp:2", "missing.inp", "does not exist"});
}

// A single unit tet deck with one line replaced, to provoke each error.
std::string tetDeck(const std::string& elementLines, const std::string& extra = "") {
  return "*NODE\n1, 0, 0, 0\n2, 1, 0, 0\n3, 0, 1, 0\n4, 0, 0, 1\n*ELEMENT, TYPE=C3D4, ELSET=EALL\n" + elementLines +
         extra;
}

TEST(AbaqusReader, BadInputNamesFileLineAndProblem) {
  TempDirectory dir;
  auto read = [&](const std::string& text) {
    const std::string path = dir.write("bad.inp", text);
    return [path] { readAbaqusInp(path); };
  };
  // Unknown element type (line 3).
  expectInputError(read("*NODE\n1, 0, 0, 0\n*ELEMENT, TYPE=S4R, ELSET=SHELL\n1, 1, 1, 1, 1\n"),
                   {"bad.inp:3", "unknown element type S4R"});
  expectInputError(read("*NODE\n1, 0, 0, 0\n*ELEMENT, TYPE=C3D15\n"), {"bad.inp:3", "unknown element type C3D15"});
  // Missing node id in a *NODE line (line 3).
  expectInputError(read("*NODE\n1, 0, 0, 0\n, 1, 0, 0\n"), {"bad.inp:3", "missing node id"});
  // Duplicated node id (line 3 repeats line 2).
  expectInputError(read("*NODE\n1, 0, 0, 0\n1, 1, 0, 0\n"), {"bad.inp:3", "duplicated node id 1", "bad.inp:2"});
  // Element referring to a missing node (line 7).
  expectInputError(read(tetDeck("1, 1, 2, 3, 99\n")), {"bad.inp:7", "element 1", "missing node 99"});
  // Bad number in a coordinate (line 2).
  expectInputError(read("*NODE\n1, 0, 0x, 0\n"), {"bad.inp:2", "bad number '0x'", "node 1"});
  // Too few nodes and no continuation comma (line 7).
  expectInputError(read(tetDeck("1, 1, 2, 3\n")), {"bad.inp:7", "element 1 has 3 nodes", "C3D4 has 4"});
  // Duplicated element id (line 8).
  expectInputError(read(tetDeck("1, 1, 2, 3, 4\n1, 1, 2, 3, 4\n")), {"bad.inp:8", "duplicated element id 1"});
  // Set referring to a missing node (line 9), a missing element (line 9), a missing set (line 9).
  expectInputError(read(tetDeck("1, 1, 2, 3, 4\n", "*NSET, NSET=FIX\n1, 42\n")),
                   {"bad.inp:9", "node set 'FIX' refers to missing node 42"});
  expectInputError(read(tetDeck("1, 1, 2, 3, 4\n", "*ELSET, ELSET=E2\n5\n")),
                   {"bad.inp:9", "element set 'E2' refers to missing element 5"});
  expectInputError(read(tetDeck("1, 1, 2, 3, 4\n", "*ELSET, ELSET=E2\nNOPE\n")),
                   {"bad.inp:9", "element set 'E2' refers to missing element set 'NOPE'"});
  expectInputError(read(tetDeck("1, 1, 2, 3, 4\n", "*NSET, NSET=N2, GENERATE\n1, 6, 1\n")),
                   {"bad.inp:9", "node set 'N2' refers to missing node 5"});
  // Empty set (defined on line 8, never filled).
  expectInputError(read(tetDeck("1, 1, 2, 3, 4\n", "*NSET, NSET=EMPTY\n*STEP\n")),
                   {"bad.inp:8", "node set 'EMPTY' is empty"});
  // Inverted element: nodes 2 and 3 swapped (line 7).
  expectInputError(read(tetDeck("1, 1, 3, 2, 4\n")),
                   {"bad.inp:7", "element 1 (block 'EALL')", "inverted or degenerate", "-1 is not positive"});
  // Degenerate element: node 4 in the plane of the others.
  expectInputError(read("*NODE\n1, 0, 0, 0\n2, 1, 0, 0\n3, 0, 1, 0\n4, 1, 1, 0\n*ELEMENT, TYPE=C3D4\n5, 1, 2, 3, 4\n"),
                   {"bad.inp:7", "element 5", "inverted or degenerate"});
  // No elements at all.
  expectInputError(read("*NODE\n1, 0, 0, 0\n"), {"bad.inp", "no elements"});
  // Ids outside 1..2^31-1 (a larger one failed only at the Exodus write; issue 20), and
  // coordinates that are not finite numbers (NaN gave "det J = nan" without the line).
  expectInputError(read("*NODE\n0, 0, 0, 0\n"), {"bad.inp:2", "node id 0 must lie in 1..2147483647"});
  expectInputError(read("*NODE\n-3, 0, 0, 0\n"), {"bad.inp:2", "node id -3 must lie in 1..2147483647"});
  expectInputError(read("*NODE\n3000000000, 0, 0, 0\n"), {"bad.inp:2", "node id 3000000000 must lie"});
  expectInputError(read(tetDeck("0, 1, 2, 3, 4\n")), {"bad.inp:7", "must lie in 1..2147483647"});
  expectInputError(read("*NODE\n1, 0, nan, 0\n"), {"bad.inp:2", "'nan'", "coordinate 2 of node 1", "not a finite"});
  expectInputError(read("*NODE\n1, 0, 0, inf\n"), {"bad.inp:2", "'inf'", "not a finite"});
  // Missing file.
  expectInputError([&] { readAbaqusInp(dir.file("nothere.inp")); }, {"nothere.inp", "does not exist"});
}

TEST(AbaqusWriter, RoundTripKeepsNodesElementsAndSets) {
  TempDirectory dir;
  Mesh original = readAbaqusInp(dir.write("cubes.inp", kTwoHexDeck));
  // Coordinates that need all 16 digits, and a hex20 block needing a continuation line.
  original.coords[0] = {1.0 / 3.0, -2.0 / 7.0, 1e-9 / 3.0};
  const std::string written = dir.file("written.inp");
  writeAbaqusInp(written, original);
  const Mesh back = readAbaqusInp(written);
  ASSERT_EQ(back.numNodes(), original.numNodes());
  EXPECT_EQ(back.nodeIds, original.nodeIds);
  for (Index n = 0; n < back.numNodes(); ++n)
    for (int d = 0; d < 3; ++d)
      EXPECT_NEAR(back.coords[n][d], original.coords[n][d], 1e-15 * std::max(1.0, std::abs(original.coords[n][d])));
  ASSERT_EQ(back.blocks.size(), 1u);
  EXPECT_EQ(back.blocks[0].name, "CUBES");
  EXPECT_EQ(back.blocks[0].connectivity, original.blocks[0].connectivity);
  EXPECT_EQ(back.blocks[0].elementIds, original.blocks[0].elementIds);
  EXPECT_EQ(back.nodeSets, original.nodeSets);
  EXPECT_EQ(back.elementSets, original.elementSets);
  // The writer leaves no temporary behind.
  EXPECT_EQ(dir.entries().size(), 2u);
}

TEST(AbaqusWriter, Hex20RoundTripUsesContinuationLines) {
  TempDirectory dir;
  Mesh mesh;
  mesh.source = "hand-made brick";
  const auto ref = referenceNodes(ElementType::Hex20);  // [-1,1]^3 with mid-edge nodes
  for (int a = 0; a < 20; ++a) mesh.coords.push_back({ref(a, 0), ref(a, 1), ref(a, 2)});
  ElementBlock block;
  block.name = "brick";
  block.type = ElementType::Hex20;
  for (int a = 0; a < 20; ++a) block.connectivity.push_back(a);
  mesh.blocks.push_back(block);
  mesh.nodeSets["top"] = {4, 5, 6, 7, 12, 13, 14, 15};
  const std::string path = dir.file("brick.inp");
  writeAbaqusInp(path, mesh);  // no ids in the mesh: 1..n
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_NE(text.str().find("*ELEMENT, TYPE=C3D20, ELSET=brick\n1, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15,\n"
                            "16, 17, 18, 19, 20\n"),
            std::string::npos)
      << text.str();
  const Mesh back = readAbaqusInp(path);
  EXPECT_NEAR(meshVolume(back), 8.0, 1e-14);
  EXPECT_EQ(back.blocks[0].connectivity, mesh.blocks[0].connectivity);
  EXPECT_EQ(back.nodeSet("top"), mesh.nodeSets["top"]);
}

TEST(AbaqusWriter, FailureLeavesNoFile) {
  TempDirectory dir;
  const Mesh mesh = readAbaqusInp(dir.write("cubes.inp", kTwoHexDeck));
  // Output directory that does not exist.
  const std::string nowhere = dir.file("no/such/dir/out.inp");
  expectInputError([&] { writeAbaqusInp(nowhere, mesh); }, {"out.inp", "does not exist"});
  EXPECT_FALSE(std::filesystem::exists(nowhere));
  // A broken mesh is refused before anything is written.
  Mesh broken = mesh;
  broken.blocks[0].connectivity[3] = 99;
  expectInputError([&] { writeAbaqusInp(dir.file("broken.inp"), broken); }, {"refers to node index 99"});
  EXPECT_FALSE(std::filesystem::exists(dir.file("broken.inp")));
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"cubes.inp"});
}

}  // namespace
