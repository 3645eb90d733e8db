// The cyclic transform's structure: unknown counts per k, the phase relation on
// the right face, axis nodes, and errors.
#include <gtest/gtest.h>

#include <cmath>

#include "cyclone/core/Error.hpp"
#include "cyclone/cyclic/CyclicTransform.hpp"

using namespace cyclone;

namespace {
// Three nodes: 0 interior, 1 left face, 2 right face (= node 1 rotated by 2pi/N about z).
cyclic::CyclicSector threeNodes(int N) {
  cyclic::CyclicSector s;
  s.sectors = N;
  s.left = {1};
  s.right = {2};
  return s;
}
}  // namespace

TEST(CyclicTransform, UnknownCountsAndRightFacePhase) {
  const int N = 8;
  const auto sector = threeNodes(N);
  const std::vector<char> fixed(9, 0);
  const Eigen::Matrix3d Q = sector.rotation();
  for (int k = 0; k <= N / 2; ++k) {
    const auto T = cyclic::cyclicTransform(3, sector, k, fixed, Q);
    const int copies = cyclic::copiesFor(N, k);
    EXPECT_EQ(T.copies(), copies);
    EXPECT_EQ(T.numEquations(), 6 * copies);  // nodes 0 and 1, 3 components, per copy
    // A random reduced vector: the right face must be Re/Im of e^{i phi} Q (a_L + i b_L).
    Eigen::VectorXd x = Eigen::VectorXd::Random(T.numEquations());
    auto value = [&](int node, int d, int copy) {
      double v = 0;
      for (const auto& t : T.terms(node, d, copy)) v += t.coefficient * x(t.equation);
      return v;
    };
    Eigen::Vector3d a, b, ra, rb;
    for (int d = 0; d < 3; ++d) {
      a(d) = value(1, d, 0);
      b(d) = copies == 2 ? value(1, d, 1) : 0.0;
      ra(d) = value(2, d, 0);
      rb(d) = copies == 2 ? value(2, d, 1) : 0.0;
    }
    const double phi = 2 * M_PI * k / N;
    EXPECT_LT((ra - Q * (std::cos(phi) * a - std::sin(phi) * b)).norm(), 1e-14) << "k " << k;
    if (copies == 2) {
      EXPECT_LT((rb - Q * (std::sin(phi) * a + std::cos(phi) * b)).norm(), 1e-14) << "k " << k;
    }
  }
}

// Every unknown's master DOF (where the rigid-body near null space is sampled) lies
// on the node that owns it, so the unknowns come blocked by node (3 x copies each),
// as MueLu's aggregation needs, for every k. The right face must not take a master
// even where it carries a left unknown alone (k = 0: the axial component, Q_zz = 1).
// Node 0 is the right face here: it comes first in physical order.
TEST(CyclicTransform, MastersOnTheOwningNodeSoUnknownsAreBlockedByNode) {
  const int N = 8;
  cyclic::CyclicSector sector;
  sector.sectors = N;
  sector.left = {1};
  sector.right = {0};
  const std::vector<char> fixed(9, 0);
  for (int k = 0; k <= N / 2; ++k) {
    const auto T = cyclic::cyclicTransform(3, sector, k, fixed, sector.rotation());
    EXPECT_TRUE(T.blockedByNode()) << "k " << k;
    for (long long e = 0; e < T.numEquations(); ++e) EXPECT_NE(T.masterDof()[e] / 3, 0) << "k " << k << " unknown " << e;
  }
}

TEST(CyclicTransform, AxisNodeKeepsOnlyAllowedMotions) {
  // A node on the axis of an 8-sector model: axial motion for k = 0, in-plane
  // (one travelling pair: 2 unknowns over the two copies) for k = 1, nothing beyond.
  cyclic::CyclicSector s;
  s.sectors = 8;
  s.left = {0};
  s.right = {0};
  const std::vector<char> fixed(3, 0);
  const int expected[] = {1, 2, 0, 0, 0};
  for (int k = 0; k <= 4; ++k)
    EXPECT_EQ(cyclic::cyclicTransform(1, s, k, fixed, s.rotation()).numEquations(), expected[k]) << "k " << k;
}

// Multiplication by i (the travelling-wave phase) maps unknown 2m to 2m+1 for every
// 0 < k < N/2, also for an axis node's in-plane pair (k = 1) and with the right face
// first; k = 0 and N/2 have one copy and no pairs. A numbering with the copies
// swapped on one node is caught.
TEST(CyclicTransform, UnknownsPairForTheTravellingWaveSplit) {
  const int N = 8;
  cyclic::CyclicSector axis;
  axis.sectors = N;
  axis.left = {0, 2};
  axis.right = {0, 1};
  const std::vector<char> fixed(9, 0);
  for (const auto& sector : {threeNodes(N), axis})
    for (int k = 0; k <= N / 2; ++k) {
      const auto T = cyclic::cyclicTransform(3, sector, k, fixed, sector.rotation());
      EXPECT_EQ(cyclic::travellingWavePaired(T), k > 0 && 2 * k < N) << "k " << k;
    }
  fe::DofTransform swapped(1, 2);
  for (int d = 0; d < 3; ++d) {
    const long long a = 2 * d, b = 2 * d + 1;
    swapped.set(0, d, 0, {{d == 1 ? b : a, 1.0}});
    swapped.set(0, d, 1, {{d == 1 ? a : b, 1.0}});
  }
  swapped.finalize(6);
  EXPECT_FALSE(cyclic::travellingWavePaired(swapped));
}

TEST(CyclicTransform, BadHarmonicIndexAndAsymmetricFixityAreErrors) {
  const auto sector = threeNodes(6);
  const std::vector<char> free(9, 0);
  EXPECT_THROW(cyclic::cyclicTransform(3, sector, 4, free, sector.rotation()), InputError);
  EXPECT_THROW(cyclic::cyclicTransform(3, sector, -1, free, sector.rotation()), InputError);
  std::vector<char> fixedRightOnly(9, 0);
  fixedRightOnly[6] = fixedRightOnly[7] = fixedRightOnly[8] = 1;
  EXPECT_THROW(cyclic::cyclicTransform(3, sector, 1, fixedRightOnly, sector.rotation()), InputError);
}
