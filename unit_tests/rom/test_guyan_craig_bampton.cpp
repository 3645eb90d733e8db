// rom::GuyanModel and rom::CraigBamptonModel on small dense chains, built from a
// BoundaryReduction computed here the textbook way (DenseSystems.hpp), against
// the exact dense receptance ((1 + i eta) K - w^2 M)^{-1} at the retained DOFs
// and the full model's eigenvalues:
//   Guyan: exact at w = 0 (K_g^{-1} is the retained block of K^{-1}), exact to
//   O(w^2) so its error grows like w^4, natural frequencies above the full ones;
//   Craig-Bampton: with every fixed-interface mode kept it is the full model
//   (eigenvalues and receptance), and its eigenvalues fall monotonically to the
//   full ones from above as modes are added (nested Ritz subspaces).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "DenseSystems.hpp"
#include "cyclone/core/Error.hpp"
#include "cyclone/rom/CraigBamptonModel.hpp"
#include "cyclone/rom/GuyanModel.hpp"

using namespace cyclone;
using namespace rom_test;

namespace {

// A 12-mass graded chain seen at a mid mass, the tip and one near the root.
DenseSystem testChain() { return reordered(gradedChain(12), {6, 11, 2}); }
constexpr Index kRetained = 3;

}  // namespace

TEST(RomGuyan, ExactAtZeroFrequency) {
  const DenseSystem s = testChain();
  const double eta = 0.02;
  const rom::GuyanModel guyan(boundaryReduction(s, kRetained), eta);
  ASSERT_EQ(guyan.size(), kRetained);
  // Closed form: the statically condensed compliance is the retained block of K^{-1}.
  const Eigen::MatrixXd flexibility = s.K.inverse().topLeftCorner(kRetained, kRetained);
  const double staticErr = relativeError(guyan.zeroFrequencyCompliance(), flexibility);
  // With structural damping the w = 0 receptance is that over (1 + i eta).
  const double dampedErr = relativeError(guyan.compliance(0.0), exactReceptance(s, kRetained, 0.0, eta));
  std::printf("Guyan at w = 0: undamped %.2e, damped %.2e\n", staticErr, dampedErr);
  EXPECT_LT(staticErr, 1e-10);
  EXPECT_LT(dampedErr, 1e-10);
}

// Guyan's series in w^2 matches the exact one in its first two terms (K_g^{-1} and
// K_g^{-1} M_g K_g^{-1} = (K^{-1} M K^{-1})_bb), not in the third (interior inertia
// is only carried along statically): halving w divides the error by 16 + O(w^2 / w_1^2).
TEST(RomGuyan, ErrorGrowsLikeOmegaToTheFourth) {
  const DenseSystem s = testChain();
  const rom::GuyanModel guyan(boundaryReduction(s, kRetained), 0.0);
  const double w1 = fullModes(s).omega(0), w = 0.05 * w1;
  const double big = relativeError(guyan.compliance(w), exactReceptance(s, kRetained, w, 0.0));
  const double small = relativeError(guyan.compliance(w / 2), exactReceptance(s, kRetained, w / 2, 0.0));
  std::printf("Guyan error at 0.05 w1: %.3e, at 0.025 w1: %.3e, ratio %.4f\n", big, small, big / small);
  EXPECT_GT(big, 1e-9);  // well above round-off, so the ratio means something
  // 16 (1 + c (w / w1)^2) with c of order one: (0.05)^2 leaves it within 1 % of 16.
  EXPECT_NEAR(big / small, 16.0, 0.16);
}

// Rayleigh-Ritz: the Guyan model is the full model on the subspace of constraint
// modes, so its j-th eigenvalue is at or above the full model's j-th.
TEST(RomGuyan, NaturalFrequenciesAboveTheFullModel) {
  const DenseSystem s = testChain();
  const rom::GuyanModel guyan(boundaryReduction(s, kRetained), 0.0);
  const FullModes full = fullModes(s);
  const auto& g = guyan.modes().eigenvalues;
  ASSERT_EQ(int(g.size()), kRetained);
  for (int j = 0; j < kRetained; ++j) {
    std::printf("mode %d: Guyan %.6e, full %.6e (rad/s)^2\n", j, g[j], full.eigenvalues(j));
    EXPECT_GE(g[j], full.eigenvalues(j) * (1 - 1e-12)) << "mode " << j;
  }
  // The lowest one is close (the static shapes hold most of the first mode) but not exact.
  EXPECT_GT(g[0] / full.eigenvalues(0) - 1, 1e-6);
  EXPECT_LT(g[0] / full.eigenvalues(0) - 1, 0.5);
}

TEST(RomCraigBampton, AllInterfaceModesIsTheFullModel) {
  const DenseSystem s = testChain();
  const double eta = 0.015;
  const auto reduction = boundaryReduction(s, kRetained);
  const int interior = reduction.numInterfaceModes();
  const rom::CraigBamptonModel cb(reduction, interior, eta);
  ASSERT_EQ(cb.size(), kRetained);
  ASSERT_EQ(cb.numInterfaceModes(), interior);
  const FullModes full = fullModes(s);
  const auto& l = cb.modes().eigenvalues;
  ASSERT_EQ(int(l.size()), int(s.size()));
  double worstValue = 0;
  for (int j = 0; j < int(s.size()); ++j) worstValue = std::max(worstValue, std::abs(l[j] / full.eigenvalues(j) - 1));
  // Below, between and above the resonances (midway in w between neighbours, and past the last).
  double worstReceptance = 0;
  std::vector<double> omegas{0.0, 0.5 * full.omega(0)};
  for (int j = 0; j + 1 < int(s.size()); ++j) omegas.push_back(0.5 * (full.omega(j) + full.omega(j + 1)));
  omegas.push_back(1.3 * full.omega(int(s.size()) - 1));
  for (double w : omegas)
    worstReceptance = std::max(worstReceptance, relativeError(cb.compliance(w), exactReceptance(s, kRetained, w, eta)));
  const double staticErr =
      relativeError(cb.zeroFrequencyCompliance(), Eigen::MatrixXd(s.K.inverse().topLeftCorner(kRetained, kRetained)));
  std::printf("Craig-Bampton, all %d interface modes: eigenvalues %.2e, receptance %.2e (%zu frequencies), "
              "static %.2e\n",
              interior, worstValue, worstReceptance, omegas.size(), staticErr);
  EXPECT_LT(worstValue, 1e-10);
  EXPECT_LT(worstReceptance, 1e-10);
  EXPECT_LT(staticErr, 1e-10);
}

TEST(RomCraigBampton, ConvergesFromAboveAsModesAreAdded) {
  const DenseSystem s = testChain();
  const auto reduction = boundaryReduction(s, kRetained);
  const FullModes full = fullModes(s);
  const int interior = reduction.numInterfaceModes();
  const double w = 0.5 * (full.omega(1) + full.omega(2)), eta = 0.01;
  const auto exact = exactReceptance(s, kRetained, w, eta);
  std::vector<double> previous;
  double previousErr = 1e300;
  for (int m = 1; m <= interior; ++m) {
    const rom::CraigBamptonModel cb(reduction, m, eta);
    const auto& l = cb.modes().eigenvalues;
    ASSERT_EQ(int(l.size()), kRetained + m);
    // Rayleigh-Ritz: above the full model's; the subspaces are nested, so no eigenvalue rises with m.
    for (int j = 0; j < int(l.size()); ++j) {
      EXPECT_GE(l[j], full.eigenvalues(j) * (1 - 1e-12)) << "m " << m << " mode " << j;
      if (j < int(previous.size())) {
        EXPECT_LE(l[j], previous[j] * (1 + 1e-12)) << "m " << m << " mode " << j;
      }
    }
    previous = l;
    // Exact at w = 0 whatever m.
    EXPECT_LT(relativeError(cb.compliance(0.0), exactReceptance(s, kRetained, 0.0, eta)), 1e-10) << "m " << m;
    const double err = relativeError(cb.compliance(w), exact);
    std::printf("Craig-Bampton m = %2d: first eigenvalue +%.2e, receptance between modes 2 and 3 %.2e\n", m,
                l[0] / full.eigenvalues(0) - 1, err);
    // Each added mode takes one more interior frequency out of the error (observed
    // monotone for this chain; the last model is exact).
    EXPECT_LT(err, previousErr) << "m " << m;
    previousErr = err;
  }
  EXPECT_LT(previousErr, 1e-10);
}

TEST(RomCraigBampton, ModeCountIsChecked) {
  const auto reduction = boundaryReduction(testChain(), kRetained);
  EXPECT_THROW(rom::CraigBamptonModel(reduction, 0, 0.01), InputError);
  EXPECT_THROW(rom::CraigBamptonModel(reduction, reduction.numInterfaceModes() + 1, 0.01), InputError);
}
