// The cyclic transform on matrix-defined sectors (lumped models: one scalar DOF
// per "node", the x component; Q = identity), reduced densely as
// sum_c T_c^T A T_c, against closed forms and published values.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>

#include "cyclone/cyclic/CyclicTransform.hpp"

using namespace cyclone;

namespace {

// A lumped sector: n scalar DOFs (x components of n "nodes"); K and M given on them.
struct LumpedSector {
  int n;
  Eigen::MatrixXd K, M;
  cyclic::CyclicSector sector;
};

// Eigenvalues (rad/s)^2 of the sector reduced at nodal diameter k, ascending.
Eigen::VectorXd reducedEigenvalues(const LumpedSector& s, int k) {
  std::vector<char> fixed(3 * s.n, 0);
  for (int i = 0; i < s.n; ++i) fixed[3 * i + 1] = fixed[3 * i + 2] = 1;  // only x is a DOF
  const auto T = cyclic::cyclicTransform(s.n, s.sector, k, fixed, Eigen::Matrix3d::Identity());
  Eigen::MatrixXd Kr = Eigen::MatrixXd::Zero(T.numEquations(), T.numEquations()), Mr = Kr;
  for (int c = 0; c < T.copies(); ++c) {
    Eigen::MatrixXd Tc = Eigen::MatrixXd::Zero(s.n, T.numEquations());
    for (int i = 0; i < s.n; ++i)
      for (const auto& t : T.terms(i, 0, c)) Tc(i, t.equation) += t.coefficient;
    Kr += Tc.transpose() * s.K * Tc;
    Mr += Tc.transpose() * s.M * Tc;
  }
  // Massless DOFs (none here after reduction) would make M singular; these sectors have none.
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(Kr, Mr);
  return es.eigenvalues();
}

void spring(Eigen::MatrixXd& K, int a, int b, double k) {
  K(a, a) += k;
  K(b, b) += k;
  K(a, b) -= k;
  K(b, a) -= k;
}

}  // namespace

// Seed chapter 6: one mass per sector, spring kb to ground, kc to the neighbour:
// w^2 = (kb + 4 kc sin^2(k pi / N)) / m, single for k = 0 and N/2, double otherwise.
TEST(LumpedChains, OneDofPerSectorClosedForm) {
  for (int N : {7, 12}) {
    const double m = 2.0, kb = 1.0e4, kc = 3.0e3;
    LumpedSector s{2, Eigen::MatrixXd::Zero(2, 2), Eigen::MatrixXd::Zero(2, 2), {}};
    s.K(0, 0) = kb;
    spring(s.K, 0, 1, kc);  // node 1 is the next sector's mass (right face)
    s.M(0, 0) = m;
    s.sector.sectors = N;
    s.sector.left = {0};
    s.sector.right = {1};
    for (int k = 0; k <= N / 2; ++k) {
      const auto w2 = reducedEigenvalues(s, k);
      const double exact = (kb + 4 * kc * std::pow(std::sin(k * M_PI / N), 2)) / m;
      const int multiplicity = (k == 0 || 2 * k == N) ? 1 : 2;
      ASSERT_EQ(w2.size(), multiplicity) << "N " << N << " k " << k;
      for (int i = 0; i < multiplicity; ++i) EXPECT_NEAR(w2(i) / exact, 1.0, 1e-13) << "N " << N << " k " << k;
    }
  }
}

// The 24-sector lumped blisk of Laxalde et al. 2007 (pyHarm tutorial 6): disc
// mass m0 on kg to ground, blade masses mb1, mb2 on kb1, kb2 in series, discs
// coupled by k0. Published: first family 88.264 (ND 0), 169.344, 189.302,
// 193.050, 194.333 ... 195.676 (ND 12) Hz; second family ND 0: 249.312 Hz.
TEST(LumpedChains, LaxaldeBlisk) {
  const double m0 = 1.2, mb1 = 0.35, mb2 = 0.25, kg = 6e5, kb1 = 1e6, kb2 = 2e6, k0 = 5e7;
  LumpedSector s{4, Eigen::MatrixXd::Zero(4, 4), Eigen::MatrixXd::Zero(4, 4), {}};
  s.K(0, 0) += kg;
  spring(s.K, 0, 1, kb1);
  spring(s.K, 1, 2, kb2);
  spring(s.K, 0, 3, k0);  // node 3: the next sector's disc
  s.M(0, 0) = m0;
  s.M(1, 1) = mb1;
  s.M(2, 2) = mb2;
  s.sector.sectors = 24;
  s.sector.left = {0};
  s.sector.right = {3};
  auto hz = [](double w2) { return std::sqrt(w2) / (2 * M_PI); };
  const std::pair<int, double> firstFamily[] = {{0, 88.264}, {1, 169.344}, {2, 189.302},
                                                {3, 193.050}, {4, 194.333}, {12, 195.676}};
  std::printf("Laxalde blisk, first family:");
  for (auto [k, published] : firstFamily) {
    const double f = hz(reducedEigenvalues(s, k)(0));
    std::printf(" ND%d %.3f (%.3f)", k, f, published);
    EXPECT_NEAR(f, published, 0.0015) << "ND " << k;  // published to 3 decimals
  }
  std::printf("\n");
  EXPECT_NEAR(hz(reducedEigenvalues(s, 0)(1)), 249.312, 0.0015);
}

// Seed chapter 6.5: 2 DOF per sector (disc md on kd, blade mb on kb, discs
// coupled by kc). Per nodal diameter l the frequencies are the roots of
//   mb md w^4 - [(kd + keq + kb) mb + kb md] w^2 + (kd + keq) kb = 0,  keq = 4 kc sin^2(l theta / 2),
// and the two families veer where the disc-alone frequency crosses the blade's.
TEST(LumpedChains, TwoDofPerSectorVeering) {
  const int N = 12;
  const double md = 1.0, mb = 0.2, kd = 1e3, kb = 800.0, kc = 2e3;
  LumpedSector s{3, Eigen::MatrixXd::Zero(3, 3), Eigen::MatrixXd::Zero(3, 3), {}};
  s.K(0, 0) += kd;
  spring(s.K, 0, 1, kb);
  spring(s.K, 0, 2, kc);  // node 2: the next sector's disc
  s.M(0, 0) = md;
  s.M(1, 1) = mb;
  s.sector.sectors = N;
  s.sector.left = {0};
  s.sector.right = {2};
  double smallestGap = 1e300;
  int veeringAt = -1;
  for (int l = 0; l <= N / 2; ++l) {
    const double keq = 4 * kc * std::pow(std::sin(l * M_PI / N), 2);
    const double a = mb * md, b = -((kd + keq + kb) * mb + kb * md), c = (kd + keq) * kb;
    const double disc = std::sqrt(b * b - 4 * a * c);
    const double low = (-b - disc) / (2 * a), high = (-b + disc) / (2 * a);
    const auto w2 = reducedEigenvalues(s, l);
    const int m = (l == 0 || 2 * l == N) ? 1 : 2;
    ASSERT_EQ(w2.size(), 2 * m);
    EXPECT_NEAR(w2(0) / low, 1.0, 1e-12) << "l " << l;
    EXPECT_NEAR(w2(m) / high, 1.0, 1e-12) << "l " << l;
    if (std::sqrt(high) - std::sqrt(low) < smallestGap) smallestGap = std::sqrt(high) - std::sqrt(low), veeringAt = l;
  }
  // The disc-alone frequency (kd + keq) / md crosses the blade's kb / mb = 4000 at l = 2.5.
  EXPECT_TRUE(veeringAt == 2 || veeringAt == 3) << "closest approach at l = " << veeringAt;
}
