// Gmsh: the node order conversion checked against gmsh's own reference elements,
// and meshes built with the gmsh API here (a box), written to .msh and read back:
// counts against gmsh's, volume against the box's, mid-edge nodes at mid-edges.
#include <gtest/gtest.h>
#include <vector>
#include <sstream>
#include <iterator>
#include <fstream>
#include <cstring>

#include <gmsh.h>

#include <cmath>
#include <set>

#include "MeshTestSupport.hpp"
#include "cyclone/mesh/GmshIO.hpp"
#include "cyclone/mesh/GmshNodeOrder.hpp"
#include "cyclone/mesh/MeshGeometryCheck.hpp"
#include "cyclone/mesh/ReferenceElement.hpp"

using namespace cyclone::mesh;
using cyclone::mesh::testing::expectInputError;
using cyclone::mesh::testing::maxMidEdgeOffset;
using cyclone::mesh::testing::meshVolume;
using cyclone::mesh::testing::TempDirectory;

namespace {

struct GmshSession {
  GmshSession() {
    gmsh::initialize(0, nullptr, false);
    gmsh::option::setNumber("General.Terminal", 0);
  }
  ~GmshSession() { gmsh::finalize(); }
};

// gmsh's reference nodes, reordered by the conversion, must be Cyclone's reference nodes.
TEST(GmshNodeOrder, MapsGmshReferenceNodesOntoCyclones) {
  GmshSession session;
  for (ElementType type : {ElementType::Tet4, ElementType::Tet10, ElementType::Hex8, ElementType::Hex20}) {
    std::string name;
    int dim = 0, order = 0, numNodes = 0, numPrimary = 0;
    std::vector<double> local;
    gmsh::model::mesh::getElementProperties(gmshElementType(type), name, dim, order, numNodes, local, numPrimary);
    SCOPED_TRACE(name);
    ASSERT_EQ(dim, 3);
    ASSERT_EQ(numNodes, nodesPerElement(type));
    EXPECT_EQ(elementTypeFromGmsh(gmshElementType(type)), type);
    const auto ours = referenceNodes(type);
    const auto& fromGmsh = gmshNodeForExodusNode(type);
    ASSERT_EQ(static_cast<int>(fromGmsh.size()), numNodes);
    EXPECT_EQ(std::set<int>(fromGmsh.begin(), fromGmsh.end()).size(), fromGmsh.size());  // a permutation
    // gmsh's tetrahedron is the unit one and its hexahedron is [-1,1]^3, like ours: no coordinate map needed.
    for (int i = 0; i < numNodes; ++i)
      for (int d = 0; d < 3; ++d)
        EXPECT_NEAR(local[3 * fromGmsh[i] + d], ours(i, d), 1e-14) << "Exodus node " << i << ", coordinate " << d;
  }
  EXPECT_FALSE(elementTypeFromGmsh(6).has_value());   // prism
  EXPECT_FALSE(elementTypeFromGmsh(12).has_value());  // hex27
}

// A 2 x 1 x 0.5 box meshed with tet10, a named volume and a named face x = 0.
struct BoxCounts {
  std::size_t nodes = 0, tet10 = 0, nodesOnFixedFace = 0;
};

BoxCounts meshTet10Box(const std::string& mshPath) {
  gmsh::model::add("box");
  const int box = gmsh::model::occ::addBox(0, 0, 0, 2, 1, 0.5);
  gmsh::model::occ::synchronize();
  gmsh::model::addPhysicalGroup(3, {box}, 11);
  gmsh::model::setPhysicalName(3, 11, "solid");
  gmsh::vectorpair faces;
  gmsh::model::getEntitiesInBoundingBox(-1e-6, -1e-6, -1e-6, 1e-6, 1 + 1e-6, 0.5 + 1e-6, faces, 2);
  EXPECT_EQ(faces.size(), 1u);
  gmsh::model::addPhysicalGroup(2, {faces[0].second}, 21);
  gmsh::model::setPhysicalName(2, 21, "fixed");
  gmsh::vectorpair origin;
  gmsh::model::getEntitiesInBoundingBox(-1e-6, -1e-6, -1e-6, 1e-6, 1e-6, 1e-6, origin, 0);
  EXPECT_EQ(origin.size(), 1u);
  gmsh::model::addPhysicalGroup(0, {origin[0].second}, 31);  // the corner at the origin, unnamed
  gmsh::option::setNumber("Mesh.CharacteristicLengthMax", 0.35);
  gmsh::option::setNumber("Mesh.ElementOrder", 2);
  gmsh::model::mesh::generate(3);
  BoxCounts counts;
  std::vector<std::size_t> nodeTags, elementTags, elementNodes;
  std::vector<double> xyz, parametric;
  gmsh::model::mesh::getNodes(nodeTags, xyz, parametric, -1, -1, false, false);
  counts.nodes = nodeTags.size();
  for (std::size_t i = 0; i < nodeTags.size(); ++i) counts.nodesOnFixedFace += std::abs(xyz[3 * i]) < 1e-12;
  gmsh::model::mesh::getElementsByType(11, elementTags, elementNodes);
  counts.tet10 = elementTags.size();
  gmsh::write(mshPath);
  return counts;
}

TEST(GmshReader, Tet10BoxMatchesGmshAndGeometry) {
  TempDirectory dir;
  const std::string path = dir.file("box.msh");
  BoxCounts counts;
  {
    GmshSession session;
    gmsh::option::setNumber("Mesh.MshFileVersion", 4.1);
    counts = meshTet10Box(path);
  }
  ASSERT_GT(counts.tet10, 20u);
  const Mesh mesh = readGmsh(path);
  EXPECT_EQ(mesh.source, path);
  EXPECT_EQ(static_cast<std::size_t>(mesh.numNodes()), counts.nodes);
  ASSERT_EQ(mesh.blocks.size(), 1u);
  EXPECT_EQ(mesh.blocks[0].name, "solid");
  EXPECT_EQ(mesh.blocks[0].type, ElementType::Tet10);
  EXPECT_EQ(static_cast<std::size_t>(mesh.blocks[0].numElements()), counts.tet10);
  EXPECT_NEAR(meshVolume(mesh), 2 * 1 * 0.5, 1e-12);
  // Straight edges: every mid-edge node at its edge's midpoint (only true in the right node order).
  EXPECT_LT(maxMidEdgeOffset(mesh), 1e-12);
  EXPECT_NO_THROW(checkElementGeometry(mesh));
  // Node set "fixed": exactly the nodes with x = 0, high-order ones included.
  const auto& fixed = mesh.nodeSet("fixed");
  EXPECT_EQ(fixed.size(), counts.nodesOnFixedFace);
  for (Index n : fixed) EXPECT_EQ(mesh.coords[n][0], 0.0);
  // The unnamed point group: the box corner at the origin.
  ASSERT_EQ(mesh.nodeSet("point_31").size(), 1u);
  EXPECT_EQ(mesh.coords[mesh.nodeSet("point_31")[0]], (Point{0, 0, 0}));
  // Ids are gmsh's tags: unique and positive.
  EXPECT_EQ(std::set<Index>(mesh.nodeIds.begin(), mesh.nodeIds.end()).size(), mesh.nodeIds.size());
  EXPECT_GT(*std::min_element(mesh.nodeIds.begin(), mesh.nodeIds.end()), 0);
}

// Structured hex20 (serendipity) box without physical groups, converted from the live model.
TEST(GmshModel, Hex20BoxWithoutPhysicalGroups) {
  GmshSession session;
  gmsh::model::add("bricks");
  gmsh::model::occ::addBox(0, 0, 0, 3, 2, 1);
  gmsh::model::occ::synchronize();
  gmsh::vectorpair curves, surfaces, volumes;
  gmsh::model::getEntities(curves, 1);
  for (const auto& [dim, tag] : curves) gmsh::model::mesh::setTransfiniteCurve(tag, 3);
  gmsh::model::getEntities(surfaces, 2);
  for (const auto& [dim, tag] : surfaces) {
    gmsh::model::mesh::setTransfiniteSurface(tag);
    gmsh::model::mesh::setRecombine(dim, tag);
  }
  gmsh::model::getEntities(volumes, 3);
  gmsh::model::mesh::setTransfiniteVolume(volumes[0].second);
  gmsh::option::setNumber("Mesh.ElementOrder", 2);
  gmsh::option::setNumber("Mesh.SecondOrderIncomplete", 1);
  gmsh::model::mesh::generate(3);

  const Mesh mesh = meshFromGmshModel("bricks");
  EXPECT_EQ(mesh.source, "bricks");
  ASSERT_EQ(mesh.blocks.size(), 1u);
  EXPECT_EQ(mesh.blocks[0].name, "HEX20");
  EXPECT_EQ(mesh.blocks[0].type, ElementType::Hex20);
  EXPECT_EQ(mesh.blocks[0].numElements(), 8);  // 2 x 2 x 2 bricks
  // 3 x 3 x 3 corner nodes + one mid-edge node on each of the 3 * 2*3*3 = 54 edges.
  EXPECT_EQ(mesh.numNodes(), 27 + 54);
  EXPECT_NEAR(meshVolume(mesh), 6.0, 1e-12);
  EXPECT_LT(maxMidEdgeOffset(mesh), 1e-12);
  EXPECT_NO_THROW(checkConsistency(mesh));
  EXPECT_NO_THROW(checkElementGeometry(mesh));
  EXPECT_TRUE(mesh.nodeSets.empty());
}

TEST(GmshModel, UnsupportedElementsAreAnInputError) {
  GmshSession session;
  gmsh::model::add("hex27");
  gmsh::model::occ::addBox(0, 0, 0, 1, 1, 1);
  gmsh::model::occ::synchronize();
  gmsh::vectorpair curves, surfaces, volumes;
  gmsh::model::getEntities(curves, 1);
  for (const auto& [dim, tag] : curves) gmsh::model::mesh::setTransfiniteCurve(tag, 2);
  gmsh::model::getEntities(surfaces, 2);
  for (const auto& [dim, tag] : surfaces) {
    gmsh::model::mesh::setTransfiniteSurface(tag);
    gmsh::model::mesh::setRecombine(dim, tag);
  }
  gmsh::model::getEntities(volumes, 3);
  gmsh::model::mesh::setTransfiniteVolume(volumes[0].second);
  gmsh::option::setNumber("Mesh.ElementOrder", 2);  // complete: 27-node hexahedra
  gmsh::model::mesh::generate(3);
  expectInputError([] { meshFromGmshModel("hex27 box"); },
                   {"hex27 box", "gmsh type", "(12)", "Mesh.SecondOrderIncomplete"});

  gmsh::model::add("empty");
  expectInputError([] { meshFromGmshModel("empty model"); }, {"empty model", "no 3D elements"});
}

namespace {
// The tet10 box written by gmsh in format 4.1, binary or ASCII; its path.
std::string writeTet10Box(TempDirectory& dir, const std::string& name, bool binary) {
  const std::string path = dir.file(name);
  GmshSession session;
  gmsh::option::setNumber("Mesh.MshFileVersion", 4.1);
  gmsh::option::setNumber("Mesh.Binary", binary ? 1 : 0);
  meshTet10Box(path);
  return path;
}
}  // namespace

// A binary file reads as the ASCII one does; a damaged count (a node block's size read at
// the wrong offset, as in a file written with padding after its int fields: 16.9 GB
// allocated for 600 bytes, issue 20) is refused before gmsh allocates anything.
TEST(GmshReader, BinaryCountsAreCheckedAgainstTheFileSize) {
  TempDirectory dir;
  const std::string path = writeTet10Box(dir, "box_binary.msh", true);
  const Mesh mesh = readGmsh(path);
  EXPECT_GT(mesh.numNodes(), 100);
  EXPECT_NEAR(meshVolume(mesh), 2 * 1 * 0.5, 1e-12);
  std::string bytes;
  {
    std::ifstream in(path, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  const auto nodes = bytes.find("$Nodes\n") + 7;  // then 4 size_t, then the first block
  auto damaged = [&](const std::string& name, std::size_t at, std::uint64_t value, bool insert) {
    std::string b = bytes;
    if (insert) b.insert(at, 4, '\0');
    else std::memcpy(&b[at], &value, 8);
    return dir.write(name, b);
  };
  expectInputError([&] { readGmsh(damaged("count.msh", nodes + 8, 1000000000000000ull, false)); },
                   {"count.msh", "the number of nodes", "damaged"});
  expectInputError([&] { readGmsh(damaged("block.msh", nodes + 32 + 12, 1ull << 40, false)); },
                   {"block.msh", "a node block's number of nodes", "damaged"});
  expectInputError([&] { readGmsh(damaged("padded.msh", nodes + 32 + 4, 0, true)); }, {"padded.msh", "binary Gmsh"});
  // The first element's first node tag outside the nodes' tags: gmsh 4.8 does not check
  // it and crashed (SIGSEGV in GModel::getMeshVertexByTag) or, for a tag that wraps
  // around its int, silently took another node (both found by fuzz_readers).
  const auto elements = bytes.find("$Elements\n") + 10;
  for (std::uint64_t tag : {4294967291ull, 1ull << 40}) {
    try {
      readGmsh(damaged("node_tag.msh", elements + 32 + 20 + 8, tag, false));
      ADD_FAILURE() << "node_tag.msh read with node tag " << tag;
    } catch (const cyclone::InputError& e) {
      EXPECT_NE(std::string(e.what()).find("node_tag.msh"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("outside the nodes' tags"), std::string::npos) << e.what();
    }
  }
}

// gmsh 4.8's ASCII reader reserves what a count says as well (issue 49: a small file whose
// node count read 4e9 took 15.6 GB, then read as the mesh it was, exit 0): each count of
// an ASCII file must fit in its bytes at the fewest a record takes in text.
TEST(GmshReader, AsciiCountsAreCheckedAgainstTheFileSize) {
  TempDirectory dir;
  const std::string path = writeTet10Box(dir, "box_ascii.msh", false);
  const Mesh mesh = readGmsh(path);
  EXPECT_NEAR(meshVolume(mesh), 2 * 1 * 0.5, 1e-12);
  std::string text;
  {
    std::ifstream in(path);
    text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  // The line after a section's header, and the first block's header after it, with one
  // count (0-based field) made 4e9.
  auto damaged = [&](const std::string& name, const std::string& section, int line, int field) {
    std::string t = text;
    std::size_t at = t.find(section + "\n") + section.size() + 1;
    for (int i = 0; i < line; ++i) at = t.find('\n', at) + 1;
    std::istringstream fields(t.substr(at, t.find('\n', at) - at));
    std::vector<std::string> values{std::istream_iterator<std::string>(fields), {}};
    values.at(std::size_t(field)) = "4000000000";
    std::string joined;
    for (const auto& v : values) joined += (joined.empty() ? "" : " ") + v;
    t.replace(at, t.find('\n', at) - at, joined);
    return dir.write(name, t);
  };
  expectInputError([&] { readGmsh(damaged("nodes.msh", "$Nodes", 0, 1)); },
                   {"nodes.msh", "ASCII Gmsh file: the number of nodes", "damaged"});
  expectInputError([&] { readGmsh(damaged("node_block.msh", "$Nodes", 1, 3)); },
                   {"node_block.msh", "a node block's number of nodes", "damaged"});
  expectInputError([&] { readGmsh(damaged("element_block.msh", "$Elements", 1, 3)); },
                   {"element_block.msh", "an element block's number of elements", "damaged"});
  expectInputError([&] { readGmsh(damaged("entities.msh", "$Entities", 0, 3)); },
                   {"entities.msh", "the number of volumes", "damaged"});
  // A section's end line missing ($EndNodes: "the gmsh model has no 3D elements", issue 49
  // probe) or a file cut after a section's start.
  std::string noEnd = text;
  noEnd.erase(noEnd.find("$EndNodes\n"), 10);
  expectInputError([&] { readGmsh(dir.write("no_end_nodes.msh", noEnd)); },
                   {"no_end_nodes.msh", "the section $Nodes opened on line", "is not closed by $EndNodes before "
                    "$Elements", "damaged"});
  expectInputError([&] { readGmsh(dir.write("cut.msh", text.substr(0, text.find("$Elements\n") + 10))); },
                   {"cut.msh", "the section $Elements opened on line", "before the file's end", "damaged"});
}

// An element naming a node tag the file never defines made gmsh 4.8 crash (SIGSEGV in
// GModel::getMeshVertexByTag, found by fuzz_readers): now an InputError naming the file.
TEST(GmshReader, AnElementWithAnUndefinedNodeIsAnErrorNotACrash) {
  TempDirectory dir;
  const std::string path = dir.file("box.msh");
  {
    GmshSession session;
    gmsh::option::setNumber("Mesh.MshFileVersion", 4.1);
    meshTet10Box(path);
  }
  std::string text;
  {
    std::ifstream in(path);
    text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  // The first tet10 line: "tag n1 ... n10" -> n1 = 99999999.
  std::istringstream lines(text.substr(text.find("$Elements\n")));
  std::string line, out = text.substr(0, text.find("$Elements\n"));
  bool done = false;
  while (std::getline(lines, line)) {
    std::istringstream cells(line);
    std::vector<std::string> c{std::istream_iterator<std::string>(cells), std::istream_iterator<std::string>()};
    if (!done && c.size() == 11) {
      c[1] = "99999999";
      line.clear();
      for (const auto& x : c) line += x + " ";
      done = true;
    }
    out += line + "\n";
  }
  ASSERT_TRUE(done);
  const std::string bad = dir.write("undefined_node.msh", out);
  try {
    readGmsh(bad);
    ADD_FAILURE() << "read";
  } catch (const cyclone::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("undefined_node.msh"), std::string::npos) << e.what();
    std::printf("%s\n", e.what());
  }
}

TEST(GmshReader, BadFilesNameTheFile) {
  TempDirectory dir;
  expectInputError([&] { readGmsh(dir.file("none.msh")); }, {"none.msh", "does not exist"});
  const std::string garbage = dir.write("garbage.msh", "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\nrubbish\n");
  expectInputError([&] { readGmsh(garbage); }, {"garbage.msh"});
}

}  // namespace
