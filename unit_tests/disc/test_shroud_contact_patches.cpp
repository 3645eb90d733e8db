// The shroud face split into patches (disc::splitIntoPatches): every point in exactly one
// patch, patches of about equal weight and compact (on a grid, the quadrants), one point
// a patch at the largest count, and counts or weights that cannot make patches refused
// naming contact/patches.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "cyclone/core/Error.hpp"
#include "cyclone/disc/ShroudContactPatches.hpp"

using namespace cyclone;

namespace {

// A rows x cols grid of unit spacing in a plane tilted out of x-y (a face is not
// axis-aligned).
std::vector<Eigen::Vector3d> grid(int rows, int cols) {
  const Eigen::Vector3d u(1, 0, 0.3), v(0, 1, 0);  // at right angles, u a little longer
  std::vector<Eigen::Vector3d> p;
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c) p.push_back(double(c) * u + double(r) * v);
  return p;
}

void expectAPartition(const std::vector<std::vector<int>>& patches, int n) {
  std::vector<int> all;
  for (const auto& p : patches) {
    EXPECT_FALSE(p.empty());
    all.insert(all.end(), p.begin(), p.end());
  }
  std::sort(all.begin(), all.end());
  ASSERT_EQ(int(all.size()), n);
  for (int i = 0; i < n; ++i) EXPECT_EQ(all[std::size_t(i)], i);
}

}  // namespace

TEST(ShroudContactPatches, AGridSplitsIntoItsQuadrants) {
  // 8 x 4 points of equal weight into 4 patches: the long side is cut first, then each
  // 4 x 4 half across its longer side (u): each patch a block of 8 neighbouring points.
  const auto p = grid(4, 8);
  const auto patches = disc::splitIntoPatches(p, std::vector<double>(p.size(), 1.0), 4);
  ASSERT_EQ(patches.size(), 4u);
  expectAPartition(patches, 32);
  for (const auto& patch : patches) {
    EXPECT_EQ(patch.size(), 8u);
    std::set<int> rows, cols;
    for (int i : patch) rows.insert(i / 8), cols.insert(i % 8);
    EXPECT_EQ(rows.size() * cols.size(), 8u) << "a patch is a block of the grid";
    EXPECT_EQ(*rows.rbegin() - *rows.begin() + 1, int(rows.size()));
    EXPECT_EQ(*cols.rbegin() - *cols.begin() + 1, int(cols.size()));
  }
}

TEST(ShroudContactPatches, PatchesHaveAboutEqualWeight) {
  // Weights growing 1..10 across the face: each patch's weight within one point's of
  // the mean (the median cut is at a point).
  const auto p = grid(6, 10);
  std::vector<double> w;
  for (std::size_t i = 0; i < p.size(); ++i) w.push_back(1.0 + double(i % 10));
  double total = 0;
  for (double x : w) total += x;
  for (int count : {2, 3, 5, 7}) {
    const auto patches = disc::splitIntoPatches(p, w, count);
    ASSERT_EQ(int(patches.size()), count);
    expectAPartition(patches, 60);
    double heaviest = 0, lightest = total;
    for (const auto& patch : patches) {
      double s = 0;
      for (int i : patch) s += w[std::size_t(i)];
      heaviest = std::max(heaviest, s), lightest = std::min(lightest, s);
    }
    // Recursive halving of the heaviest: the heaviest is at most twice the lightest
    // plus a point's weight either side of each cut.
    EXPECT_LE(heaviest, 2 * lightest + 2 * 10.0) << count << " patches";
  }
}

TEST(ShroudContactPatches, AsManyPatchesAsPointsIsOnePointEach) {
  const auto p = grid(3, 5);
  const auto patches = disc::splitIntoPatches(p, std::vector<double>(p.size(), 2.0), 15);
  ASSERT_EQ(patches.size(), 15u);
  expectAPartition(patches, 15);
  for (const auto& patch : patches) EXPECT_EQ(patch.size(), 1u);
}

TEST(ShroudContactPatches, ImpossibleCountsAndWeightsAreRefused) {
  const auto p = grid(2, 3);
  const std::vector<double> w(p.size(), 1.0);
  for (int count : {0, -1, 7}) {
    try {
      disc::splitIntoPatches(p, w, count);
      ADD_FAILURE() << count << " patches of 6 points accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("contact/patches"), std::string::npos) << e.what();
    }
  }
  auto bad = w;
  bad[2] = 0;
  EXPECT_THROW(disc::splitIntoPatches(p, bad, 2), InputError);
}
