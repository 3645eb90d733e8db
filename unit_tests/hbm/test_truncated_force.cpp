// The force a harmonic set leaves out, against closed forms:
//   - a cubic spring k3 w^3 driven by w = a cos: force k3 a^3 (3/4 cos + 1/4 cos 3),
//     so with harmonic 1 alone the dropped part is exactly a third of the kept one,
//     and with harmonics 0..3 nothing is dropped;
//   - a Jenkins element (kt in series with a slider of slip force fs) driven by
//     w = a cos: the steady loop is fs - kt a (1 - cos t) from the reversal at t = 0
//     until it reaches -fs at cos t* = 1 - 2 fs / (kt a), then -fs until t = pi, and
//     the opposite over the second half: odd harmonics whose coefficients are
//     integrals of cos and sin products over [0, t*] and [t*, pi] in closed form.
//     The sampled law's DFT meets them as the samples grow (aliasing of a kinked
//     signal, about 1 / N^2): error and time printed per sample count.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>

#include "cyclone/hbm/CubicSpring.hpp"
#include "cyclone/hbm/JenkinsElement.hpp"
#include "cyclone/hbm/TruncatedForce.hpp"

using namespace cyclone;

namespace {

std::unique_ptr<hbm::HarmonicBalanceSystem> oneDof(hbm::HarmonicSet set, int samples) {
  const Eigen::MatrixXd M = Eigen::MatrixXd::Identity(1, 1), C = Eigen::MatrixXd::Zero(1, 1), K = M;
  return std::make_unique<hbm::HarmonicBalanceSystem>(M, C, K, std::move(set), samples);
}

Eigen::VectorXd cosine(const hbm::HarmonicBalanceSystem& s, double a) {
  Eigen::VectorXd x = Eigen::VectorXd::Zero(s.numCoefficients());
  x(s.aft().harmonics().cosIndex(1)) = a;
  return x;
}

// |F_h|^2 = c_h^2 + s_h^2 of the Jenkins loop under w = a cos t (odd h; even ones vanish).
double jenkinsHarmonicSquared(double kt, double fs, double a, int h) {
  const double ts = std::acos(1 - 2 * fs / (kt * a));
  auto S = [&](int m) { return m == 0 ? ts : std::sin(m * ts) / m; };        // int_0^t* cos m t
  auto Cc = [&](int m) { return m == 0 ? 0.0 : (1 - std::cos(m * ts)) / m; };  // int_0^t* sin m t
  const double Ic = (fs - kt * a) * S(h) + kt * a * 0.5 * (S(h - 1) + S(h + 1)) + fs * std::sin(h * ts) / h;
  const double Is = (fs - kt * a) * Cc(h) + kt * a * 0.5 * (Cc(h + 1) + Cc(h - 1)) - fs * (std::cos(h * ts) + 1) / h;
  const double c = 2 / M_PI * Ic, s = 2 / M_PI * Is;
  return c * c + s * s;
}

}  // namespace

TEST(TruncatedForce, CubicSpringDropsAThirdWithHarmonicOneAndNothingWithThree) {
  const double k3 = 0.7, a = 1.3, omega = 2.0;
  auto single = oneDof(hbm::HarmonicSet({1}), 64);
  single->addElement(std::make_shared<hbm::CubicSpring>(k3), Eigen::VectorXd::Ones(1));
  const auto one = hbm::truncatedForce(*single, cosine(*single, a), omega);
  ASSERT_TRUE(one.known);
  EXPECT_NEAR(one.kept, 0.75 * k3 * a * a * a, 1e-12);
  EXPECT_NEAR(one.share, 1.0 / 3.0, 1e-12);
  EXPECT_EQ(one.largestDropped, 3);
  EXPECT_NEAR(one.largestDroppedShare, 1.0 / 3.0, 1e-12);

  auto three = oneDof(hbm::HarmonicSet::upTo(3), 64);
  three->addElement(std::make_shared<hbm::CubicSpring>(k3), Eigen::VectorXd::Ones(1));
  const auto all = hbm::truncatedForce(*three, cosine(*three, a), omega);
  ASSERT_TRUE(all.known);
  EXPECT_LT(all.share, 1e-13);
}

TEST(TruncatedForce, JenkinsLoopMeetsItsClosedFormSpectrum) {
  const double kt = 2.0, fs = 0.3, a = 0.5, omega = 1.3;
  double kept = 0, dropped = 0;  // the closed form: harmonics 1, 3 kept (0..3), odd h >= 5 dropped
  for (int h = 1; h < 200001; h += 2) (h <= 3 ? kept : dropped) += jenkinsHarmonicSquared(kt, fs, a, h);
  const double exact = std::sqrt(dropped / kept);
  double last = 1;
  for (int samples : {256, 1024, 4096}) {
    const auto started = std::chrono::steady_clock::now();
    auto s = oneDof(hbm::HarmonicSet::upTo(3), samples);
    s->addElement(std::make_shared<hbm::JenkinsElement>(kt, fs), Eigen::VectorXd::Ones(1));
    const auto t = hbm::truncatedForce(*s, cosine(*s, a), omega);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    ASSERT_TRUE(t.known);
    last = std::abs(t.share / exact - 1);
    std::printf("%d samples: dropped / kept %.8f against %.8f in closed form, error %.1e; %.1e s\n", samples, t.share,
                exact, last, seconds);
    EXPECT_NEAR(t.kept, std::sqrt(kept), 1e-3 * std::sqrt(kept));
    EXPECT_EQ(t.largestDropped, 5);
    EXPECT_NEAR(t.largestDroppedShare, std::sqrt(jenkinsHarmonicSquared(kt, fs, a, 5) / kept), 1e-3);
  }
  EXPECT_LT(last, 1e-4);
}
