// The store of a nodal diameter's mode shapes: what goes in comes out, whether held in
// memory or moved to a scratch file (before or after more shapes are added), and a
// directory that cannot take the file is named.
#include <gtest/gtest.h>

#include <filesystem>
#include <iterator>
#include <string>
#include <vector>

#include "cyclone/core/Error.hpp"
#include "cyclone/cyclic/ModeShapes.hpp"

using namespace cyclone;

namespace {

cyclic::ModeShape shape(int seed, std::size_t nodes, bool imaginary) {
  cyclic::ModeShape s;
  for (std::size_t n = 0; n < nodes; ++n) {
    s.real.push_back({seed + 0.1 * double(n), -1.0 / (seed + n + 1.0), 1e-300 * seed});
    if (imaginary) s.imag.push_back({-double(seed), 3.0 * double(n), 1e300});
  }
  return s;
}

}  // namespace

TEST(ModeShapes, ScratchFileGivesBackWhatMemoryHolds) {
  const std::string dir = std::filesystem::temp_directory_path().string();
  for (const bool imaginary : {false, true}) {
    cyclic::ModeShapes memory, file;
    for (int i = 0; i < 3; ++i) memory.push_back(shape(i, 7, imaginary)), file.push_back(shape(i, 7, imaginary));
    file.moveToScratchFile(dir);
    EXPECT_TRUE(file.inScratchFile());
    for (int i = 3; i < 5; ++i) memory.push_back(shape(i, 7, imaginary)), file.push_back(shape(i, 7, imaginary));
    ASSERT_EQ(file.size(), 5u);
    EXPECT_EQ(file.numNodes(), 7u);
    for (std::size_t i = 0; i < 5; ++i) {
      const auto expected = shape(int(i), 7, imaginary);
      EXPECT_EQ(memory[i].real, expected.real);
      EXPECT_EQ(file[i].real, expected.real);
      // No imaginary part stored: zero of the real part's size.
      const cyclic::NodalField imag = imaginary ? expected.imag : cyclic::NodalField(7, {0, 0, 0});
      EXPECT_EQ(memory[i].imag, imag);
      EXPECT_EQ(file[i].imag, imag);
    }
    // A copy reads the same; what it appends is its own.
    cyclic::ModeShapes copy = file;
    EXPECT_EQ(copy[4].real, file[4].real);
    copy.push_back(shape(9, 7, imaginary));
    EXPECT_EQ(copy[5].real, shape(9, 7, imaginary).real);
    EXPECT_EQ(file.size(), 5u);
    EXPECT_THROW((void)file[5], Error);
    for (std::size_t i = 0; i < 5; ++i) EXPECT_EQ(file[i].real, shape(int(i), 7, imaginary).real);
  }
}

TEST(ModeShapes, MismatchedShapesAndAnUnwritableDirectoryAreNamed) {
  cyclic::ModeShapes s;
  s.push_back(shape(1, 4, true));
  EXPECT_THROW(s.push_back(shape(2, 5, true)), Error);   // another number of nodes
  EXPECT_THROW(s.push_back(shape(2, 4, false)), Error);  // no imaginary part where the first had one
  try {
    s.moveToScratchFile("/nonexistent/cyclone-scratch");
    FAIL() << "no error for a missing directory";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/cyclone-scratch"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(s.inScratchFile());
  EXPECT_EQ(s[0].imag, shape(1, 4, true).imag);  // still in memory, whole
}

TEST(ModeShapes, ManyStoresShareOneScratchFile) {
  // A sweep over many speeds and nodal diameters: one descriptor, not one per store.
  auto openFiles = [] {
    return std::distance(std::filesystem::directory_iterator("/proc/self/fd"), std::filesystem::directory_iterator());
  };
  const auto before = openFiles();
  const std::string dir = std::filesystem::temp_directory_path().string();
  std::vector<cyclic::ModeShapes> stores(3000);
  for (std::size_t k = 0; k < stores.size(); ++k) {
    stores[k].push_back(shape(int(k), 3, k % 2 == 0));
    stores[k].moveToScratchFile(dir);
  }
  EXPECT_LE(openFiles() - before, 1);
  for (std::size_t k = 0; k < stores.size(); k += 499) EXPECT_EQ(stores[k][0].real, shape(int(k), 3, k % 2 == 0).real);
}
