// Hill's method: exact Floquet exponents of a linear system, and the Duffing
// curve's unstable middle branch between its two folds.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <complex>
#include <memory>
#include <optional>
#include <vector>

#include "cyclone/hbm/CubicSpring.hpp"
#include "cyclone/hbm/BifurcationFlags.hpp"
#include "cyclone/hbm/HillStability.hpp"
#include "cyclone/hbm/ReceptanceModel.hpp"

using namespace cyclone;

namespace {
// Roots of f on (0.01, 4) by bisection in the brackets where it changes sign.
template <class F>
std::vector<double> rootsOf(const F& f) {
  std::vector<double> roots;
  for (double A = 0.01; A < 4.0; A += 0.01)
    if ((f(A) > 0) != (f(A + 0.01) > 0)) {
      double lo = A, hi = A + 0.01;
      for (int i = 0; i < 60; ++i) ((f(lo) > 0) == (f(0.5 * (lo + hi)) > 0) ? lo : hi) = 0.5 * (lo + hi);
      roots.push_back(0.5 * (lo + hi));
    }
  return roots;
}
// m x'' + c x' + k x = cos(W t), harmonics 0..5 on 32 samples.
hbm::HarmonicBalanceSystem oscillator(double m, double c, double k) {
  hbm::HarmonicBalanceSystem sys(Eigen::MatrixXd::Constant(1, 1, m), Eigen::MatrixXd::Constant(1, 1, c),
                                 Eigen::MatrixXd::Constant(1, 1, k), hbm::HarmonicSet::upTo(5), 32);
  sys.addExcitation(0, 1, 1.0);
  return sys;
}
}  // namespace

TEST(HillStability, LinearOscillatorHasItsDampedEigenvaluesAsExponents) {
  // m x'' + c x' + k x = f: exponents -c/2m +- i sqrt(k/m - (c/2m)^2), whatever the forcing.
  const auto sys = oscillator(2.0, 0.3, 5.0);
  const double omega = 1.3;
  const auto fl = hbm::hillStability(sys, sys.linearSolution(omega), omega);
  ASSERT_EQ(fl.exponents.size(), 2);
  const double sigma = -0.3 / 4.0, wd = std::sqrt(5.0 / 2.0 - sigma * sigma);
  for (int i = 0; i < 2; ++i) {
    EXPECT_NEAR(fl.exponents(i).real(), sigma, 1e-10);
    // Defined modulo i omega: the imaginary part is wd shifted into (-omega/2, omega/2].
    const double shifted = std::remainder(std::abs(fl.exponents(i).imag()) - wd, omega);
    EXPECT_NEAR(shifted, 0.0, 1e-10);
  }
  EXPECT_TRUE(fl.stable);
}


// The same closed form on a stiff oscillator (k = 1e12, m = 1, c = 0.05: exponents
// -0.025 +- 1e6 i), driven near and far from resonance: unscaled, the companion matrix's
// norm of 1e12 made the eigenvalues' rounding exceed the damping, and a linear damped
// system came out unstable (real parts up to +10, issue 49 probe).
TEST(HillStability, StiffOscillatorKeepsItsSmallDamping) {
  const auto sys = oscillator(1.0, 0.05, 1e12);
  for (const double omega : {0.5e6, 0.99e6, 1.01e6, 3e6}) {
    const auto fl = hbm::hillStability(sys, sys.linearSolution(omega), omega);
    ASSERT_EQ(fl.exponents.size(), 2);
    for (int i = 0; i < 2; ++i) EXPECT_NEAR(fl.exponents(i).real(), -0.025, 1e-6) << "omega " << omega;
    EXPECT_TRUE(fl.stable) << "omega " << omega;
  }
}
TEST(HillStability, DuffingMiddleBranchIsUnstable) {
  // At W = 1.2 the Duffing curve (m = 1, c = 0.05, k = 1, g = 0.1, P = 0.18) has three
  // solutions; the middle one (between the folds) is unstable, the outer two stable.
  Eigen::MatrixXd M(1, 1), C(1, 1), K(1, 1);
  M << 1.0;
  C << 0.05;
  K << 1.0;
  hbm::HarmonicBalanceSystem sys(M, C, K, hbm::HarmonicSet::upTo(7), 64);
  sys.addElement(std::make_shared<hbm::CubicSpring>(0.1), Eigen::VectorXd::Ones(1));
  sys.addExcitation(0, 1, 0.18);
  const double W = 1.2;
  // Starts: the three single-term solutions, roots of [(s)^2 + (cW)^2] A^2 = P^2 with
  // s = k - m W^2 + 3/4 g A^2 (bisection in brackets found by sign changes), each with
  // its phase a = P s / (s^2 + c^2 W^2), b = P c W / (s^2 + c^2 W^2).
  auto f = [&](double A) {
    const double s = 1 - W * W + 0.075 * A * A;
    return (s * s + 0.0025 * W * W) * A * A - 0.18 * 0.18;
  };
  const std::vector<double> roots = rootsOf(f);
  ASSERT_EQ(roots.size(), 3u);
  int stable = 0, unstable = 0;
  std::vector<double> amplitudes;
  for (double A0 : roots) {
    const double s = 1 - W * W + 0.075 * A0 * A0, den = s * s + 0.0025 * W * W;
    Eigen::VectorXd X = Eigen::VectorXd::Zero(sys.numUnknowns()), R;
    X(sys.aft().harmonics().cosIndex(1)) = 0.18 * s / den;
    X(sys.aft().harmonics().sinIndex(1)) = 0.18 * 0.05 * W / den;
    Eigen::MatrixXd J;
    for (int it = 0; it < 50; ++it) {
      sys.residual(X, W, R, &J);
      if (R.norm() < 1e-12) break;
      X -= J.partialPivLu().solve(R);
    }
    ASSERT_LT(R.norm(), 1e-10);
    amplitudes.push_back(sys.amplitude(X, 0, 1));
    const auto fl = hbm::hillStability(sys, X, W);
    std::printf("W = %.1f, |x1| = %.5f: exponents %+.4e%+.4ei, %+.4e%+.4ei -> %s\n", W, amplitudes.back(),
                fl.exponents(0).real(), fl.exponents(0).imag(), fl.exponents(1).real(), fl.exponents(1).imag(),
                fl.stable ? "stable" : "unstable");
    (fl.stable ? stable : unstable)++;
    if (A0 == roots[1]) {
      EXPECT_FALSE(fl.stable) << "middle branch, |x1| " << amplitudes.back();
    }
  }
  EXPECT_LT(amplitudes[0], amplitudes[1]);
  EXPECT_LT(amplitudes[1], amplitudes[2]);
  EXPECT_EQ(stable, 2);
  EXPECT_EQ(unstable, 1);
}

namespace {
// A single mode with structural damping as a receptance: A(w) = 1 / ((1 + i eta) k - w^2)
// (unit mass), what a reduced model of an FE sector looks like to the harmonic balance.
class StructuralOscillator final : public hbm::ReceptanceModel {
public:
  StructuralOscillator(double k, double eta) : k_(k), eta_(eta) {}
  int numDofs() const override { return 1; }
  int sectors() const override { return 1; }
  Eigen::MatrixXcd compliance(double w, long) const override {
    return Eigen::MatrixXcd::Constant(1, 1, 1.0 / (std::complex<double>(k_, eta_ * k_) - w * w));
  }
  Eigen::MatrixXd meanCompliance() const override { return Eigen::MatrixXd::Constant(1, 1, 1.0 / k_); }
  std::optional<hbm::ModalRealization> modalRealization(long) const override {
    hbm::ModalRealization r;
    r.R = Eigen::MatrixXcd::Zero(1, 1);
    r.U = r.V = Eigen::MatrixXcd::Ones(1, 1);
    r.eigenvalues = Eigen::VectorXd::Constant(1, k_);
    r.viscous = Eigen::VectorXd::Zero(1);
    r.lossFactor = eta_;
    return r;
  }

private:
  double k_, eta_;
};
}  // namespace

TEST(HillStability, StructurallyDampedDuffingReceptanceMiddleBranchIsUnstable) {
  // x'' + (1 + i 0.05) x + 0.1 x^3 = 0.18 cos(1.2 t) in receptance form: three solutions,
  // single-term starts from [(s)^2 + eta^2] A^2 = P^2, s = 1 - W^2 + 3/4 g A^2. Hill's
  // method through the modal realization: the middle one (between the folds) unstable
  // by a real exponent (a saddle), the outer two stable.
  const double W = 1.2, eta = 0.05, P = 0.18;
  hbm::HarmonicBalanceSystem sys(std::make_shared<StructuralOscillator>(1.0, eta), hbm::HarmonicSet::upTo(7), 64);
  sys.addElement(std::make_shared<hbm::CubicSpring>(0.1), Eigen::VectorXd::Ones(1));
  sys.addExcitation(0, 1, P);
  auto f = [&](double A) {
    const double s = 1 - W * W + 0.075 * A * A;
    return (s * s + eta * eta) * A * A - P * P;
  };
  const std::vector<double> roots = rootsOf(f);
  ASSERT_EQ(roots.size(), 3u);
  std::vector<bool> stable;
  double previous = 0;
  for (double A0 : roots) {
    const double s = 1 - W * W + 0.075 * A0 * A0, den = s * s + eta * eta;
    Eigen::VectorXd X = Eigen::VectorXd::Zero(sys.numUnknowns()), R;
    X(sys.aft().harmonics().cosIndex(1)) = P * s / den;
    X(sys.aft().harmonics().sinIndex(1)) = P * eta / den;
    Eigen::MatrixXd J;
    for (int it = 0; it < 50; ++it) {
      sys.residual(X, W, R, &J);
      if (R.norm() < 1e-13) break;
      X -= J.partialPivLu().solve(R);
    }
    ASSERT_LT(R.norm(), 1e-10);
    const double amplitude = sys.amplitude(X, 0, 1);
    EXPECT_GT(amplitude, previous);  // three distinct solutions, in order
    previous = amplitude;
    const auto fl = hbm::hillStability(sys, X, W);
    std::printf("receptance, W = %.1f, |x1| = %.5f: leading exponent %+.4e%+.4ei of %d -> %s\n", W, amplitude,
                fl.exponents(0).real(), fl.exponents(0).imag(), int(fl.exponents.size()),
                fl.stable ? "stable" : "unstable");
    stable.push_back(fl.stable);
    if (!fl.stable) {
      EXPECT_NEAR(fl.exponents(0).imag(), 0.0, 1e-9);
    }
  }
  EXPECT_TRUE(stable[0]);
  EXPECT_FALSE(stable[1]);
  EXPECT_TRUE(stable[2]);
}

// Flags along synthetic curves: a fold where the parameter turns (whatever the
// exponents), and away from folds the kind of stability loss from the exponent
// that crosses: real, at i w/2, or another complex pair.
TEST(BifurcationFlags, FoldsAndTheKindOfEachCrossing) {
  using cyclone::hbm::CurvePointStability;
  const double w = 2.0;
  std::vector<CurvePointStability> c = {
      {1.0, w, 1, {-0.1, 0.3}}, {1.1, w, 1, {-0.1, 0.3}}, {1.2, w, 1, {-0.01, 0}}, {1.15, w, 0, {0.02, 0}},
      {1.1, w, 0, {0.05, 0}},   {1.05, w, 0, {0.01, 0}},  {1.1, w, 1, {-0.02, 0}}, {1.2, w, 1, {-0.1, 0.2}},
      {1.3, w, 0, {0.01, 1.0}}, {1.4, w, 1, {-0.1, 0.2}}, {1.5, w, 0, {0.01, 0.7}}, {1.6, w, 1, {-0.1, 0.2}},
      {1.7, w, 0, {0.01, 0.0}}};
  const auto f = cyclone::hbm::bifurcationFlags(c);
  EXPECT_EQ(f[2], "fold");
  EXPECT_EQ(f[5], "fold");
  EXPECT_EQ(f[3], "");  // the stability change at a fold is the fold
  EXPECT_EQ(f[8], "period_doubling");
  EXPECT_EQ(f[9], "period_doubling");  // regained: the same crossing back
  EXPECT_EQ(f[10], "neimark_sacker");
  EXPECT_EQ(f[12], "branch_point");
  EXPECT_EQ(f[1], "");
  // The path turns, but the stability is the same on both sides: no saddle-node fold.
  std::vector<CurvePointStability> t = {{1.0, w, 1, {-0.1, 0}}, {1.1, w, 1, {-0.1, 0}}, {1.2, w, 1, {-0.1, 0}},
                                        {1.1, w, 1, {-0.1, 0}}, {1.0, w, 1, {-0.1, 0}}, {0.9, w, 1, {-0.1, 0}}};
  EXPECT_EQ(cyclone::hbm::bifurcationFlags(t)[2], "turn");
  t[3].stable = 0, t[4].stable = 0, t[5].stable = 0;
  EXPECT_EQ(cyclone::hbm::bifurcationFlags(t)[2], "fold");
  for (auto& p : t) p.stable = -1;  // not computed: the path alone says fold
  EXPECT_EQ(cyclone::hbm::bifurcationFlags(t)[2], "fold");
}
