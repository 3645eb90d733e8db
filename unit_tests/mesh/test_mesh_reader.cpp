// readMesh chooses the reader by extension and names the file when it cannot.
#include <gtest/gtest.h>

#include "MeshTestSupport.hpp"
#include "cyclone/mesh/AbaqusIO.hpp"
#include "cyclone/mesh/ExodusIO.hpp"
#include "cyclone/mesh/MeshReader.hpp"

using namespace cyclone::mesh;
using cyclone::mesh::testing::expectInputError;
using cyclone::mesh::testing::TempDirectory;

namespace {

const char* kTetDeck = "*NODE\n1, 0, 0, 0\n2, 1, 0, 0\n3, 0, 1, 0\n4, 0, 0, 1\n*ELEMENT, TYPE=C3D4, ELSET=T\n1, 1, 2, 3, 4\n";

TEST(MeshReader, DispatchesByExtension) {
  TempDirectory dir;
  const Mesh fromInp = readMesh(dir.write("tet.inp", kTetDeck));
  EXPECT_EQ(fromInp.numElements(), 1);
  EXPECT_EQ(readMesh(dir.write("TET.INP", kTetDeck)).numNodes(), 4);  // case-insensitive extension
  for (const char* name : {"tet.exo", "tet.e", "tet.g", "tet.ex2", "tet.EXO"}) {
    writeExodus(dir.file(name), fromInp);
    const Mesh back = readMesh(dir.file(name));
    EXPECT_EQ(back.coords, fromInp.coords) << name;
    EXPECT_EQ(back.blocks[0].name, "T") << name;
  }
}

TEST(MeshReader, UnknownExtensionOrMissingFile) {
  TempDirectory dir;
  expectInputError([&] { readMesh(dir.write("tet.stl", kTetDeck)); }, {"tet.stl", "unknown mesh file extension '.stl'"});
  expectInputError([&] { readMesh(dir.write("noextension", kTetDeck)); }, {"noextension", "unknown mesh file extension"});
  expectInputError([&] { readMesh(dir.file("absent.inp")); }, {"absent.inp", "does not exist"});
  expectInputError([&] { readMesh(dir.file("absent.msh")); }, {"absent.msh", "does not exist"});
}

}  // namespace
