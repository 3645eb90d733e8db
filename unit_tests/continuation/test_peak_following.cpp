// The largest peak followed over a parameter, on a main mass with a tuned absorber
// (2-DOF, linear, closed-form frequency response):
//  - the absorber's tuning as the parameter, where another peak overtakes the one
//    followed: at f = 0.9 the upper peak is the larger, at f = 1.0 the lower one;
//    neither vanishes in between. Both peaks of the starting curve are followed
//    (prominentPeaks) and each value reports the largest, marked as a jump where it
//    changes: every point is the exact response's global maximum (dense sampling and
//    golden section of the closed form);
//  - the absorber's damping as the parameter, where the followed (upper) peak
//    vanishes into the other: the band's largest is taken there, marked as a jump.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstdio>

#include "cyclone/continuation/PeakFollowing.hpp"

using namespace cyclone;

namespace {

constexpr double m1 = 1, k1 = 1, c1 = 0.002, m2 = 0.05, c2 = 1e-3;

// The absorber's parameter: its tuning f (k2 = m2 f^2, damping c2) or its damping
// (tuned to 1, k2 = m2).
enum class Absorber { Tuning, Damping };
void absorberProperties(Absorber q, double p, double& k2, double& damping) {
  k2 = q == Absorber::Tuning ? m2 * p * p : m2;
  damping = q == Absorber::Tuning ? c2 : p;
}

// |X1(w)| of the main mass under a unit force, the absorber's parameter at p.
double amplitude(double w, Absorber q, double p) {
  double k2, cd;
  absorberProperties(q, p, k2, cd);
  const std::complex<double> a(k1 + k2 - m1 * w * w, w * (c1 + cd)), b(-k2, -w * cd), d(k2 - m2 * w * w, w * cd);
  return std::abs(d / (a * d - b * b));
}
double exactAmplitude(double w, double f) { return amplitude(w, Absorber::Tuning, f); }

// The global maximum over [0.7, 1.3]: the best of 60001 samples, then golden section.
std::pair<double, double> exactPeak(double f) {
  double best = 0.7, top = 0;
  for (int i = 0; i <= 60000; ++i) {
    const double w = 0.7 + 0.6 * i / 60000;
    if (const double a = exactAmplitude(w, f); a > top) top = a, best = w;
  }
  double lo = best - 1e-5, hi = best + 1e-5;
  const double g = 0.5 * (std::sqrt(5.0) - 1);
  while (hi - lo > 1e-13) {
    const double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
    (exactAmplitude(x1, f) > exactAmplitude(x2, f) ? hi : lo) = exactAmplitude(x1, f) > exactAmplitude(x2, f) ? x2 : x1;
  }
  return {0.5 * (lo + hi), exactAmplitude(0.5 * (lo + hi), f)};
}

// Harmonic balance of the linear system, x = [a1 a2 b1 b2] (cos and sin parts), in the
// absorber's parameter q.
continuation::PeakTrackingProblem absorber(Absorber q = Absorber::Tuning) {
  continuation::PeakTrackingProblem P;
  P.size = 4;
  auto blocks = [q](double w, double p, Eigen::Matrix2d& S, Eigen::Matrix2d& D) {
    double k2, cd;
    absorberProperties(q, p, k2, cd);
    Eigen::Matrix2d K, M, C;
    K << k1 + k2, -k2, -k2, k2;
    M << m1, 0, 0, m2;
    C << c1 + cd, -cd, -cd, cd;
    S = K - w * w * M, D = w * C;
  };
  P.residual = [blocks](const Eigen::VectorXd& x, double w, double p, Eigen::VectorXd& R) {
    Eigen::Matrix2d S, D;
    blocks(w, p, S, D);
    R.resize(4);
    R.head(2) = S * x.head(2) + D * x.tail(2) - Eigen::Vector2d(1, 0);
    R.tail(2) = S * x.tail(2) - D * x.head(2);
  };
  P.jacobian = [blocks](const Eigen::VectorXd&, double w, double p, Eigen::MatrixXd& J) {
    Eigen::Matrix2d S, D;
    blocks(w, p, S, D);
    J.resize(4, 4);
    J << S, D, -D, S;
  };
  P.measure = [](const Eigen::VectorXd& x) { return std::hypot(x(0), x(2)); };
  return P;
}

}  // namespace

TEST(PeakFollowing, APeakThatOvertakesTheFollowedOneIsTaken) {
  const auto P = absorber();
  // The starting curve at f = 0.9 and its peaks.
  continuation::ContinuationProblem curve;
  curve.size = 4;
  curve.residual = [&P](const Eigen::VectorXd& x, double w, Eigen::VectorXd& R) { P.residual(x, w, 0.9, R); };
  curve.jacobian = [&P](const Eigen::VectorXd& x, double w, Eigen::MatrixXd& J) { P.jacobian(x, w, 0.9, J); };
  curve.measure = P.measure;
  continuation::ContinuationOptions co;
  co.from = 0.7, co.to = 1.3;
  const auto branch = continuation::traceBranch(curve, Eigen::VectorXd::Zero(4), co);
  ASSERT_TRUE(branch.finished) << branch.stopReason;
  const auto starts = continuation::prominentPeaks(branch, P.measure);
  ASSERT_EQ(starts.size(), 2u);

  continuation::PeakFollowingOptions o;
  for (int i = 0; i <= 20; ++i) o.parameters.push_back(0.9 + 0.005 * i);
  o.search.step = 1e-4, o.search.maxStep = 1e-2, o.search.window = 0.2, o.search.parameterTolerance = 1e-9;
  o.search.tolerance = 1e-12;
  const auto followed = continuation::followPeaks(P, starts, o);
  ASSERT_TRUE(followed.complete) << followed.stopReason;
  EXPECT_EQ(followed.end, continuation::PeakFollowingEnd::RangeEnd);
  ASSERT_EQ(followed.points.size(), o.parameters.size());
  // The only jump follows the first value where the exact response's largest peak is the lower one.
  int exactSwitch = -1, jumps = 0, jumpAt = -1;
  double worstA = 0, worstW = 0;
  for (std::size_t i = 0; i < followed.points.size(); ++i) {
    const auto& p = followed.points[i];
    const auto [w, a] = exactPeak(p.parameter);
    worstA = std::max(worstA, std::abs(p.measure / a - 1));
    worstW = std::max(worstW, std::abs(p.frequency / w - 1));
    if (exactSwitch < 0 && w < 0.95) exactSwitch = int(i);
    if (p.jump) ++jumps, jumpAt = int(i);
  }
  std::printf("%zu values, %d searches, %d Newton solves; against the exact largest peak: amplitude %.1e, frequency "
              "%.1e; the largest peak changes at f = %.3f (exact: %.3f)\n",
              followed.points.size(), followed.searches, followed.solves, worstA, worstW,
              jumpAt >= 0 ? o.parameters[std::size_t(jumpAt)] : 0.0,
              exactSwitch >= 0 ? o.parameters[std::size_t(exactSwitch)] : 0.0);
  EXPECT_LT(worstA, 1e-8);
  EXPECT_LT(worstW, 1e-6);
  EXPECT_EQ(jumps, 1);
  EXPECT_EQ(jumpAt, exactSwitch);
}

namespace {

// With the absorber's damping as the parameter (tuned to 1): two peaks while it is small,
// one (between them) once the damping has merged them.
double dampedAmplitude(double w, double damping) { return amplitude(w, Absorber::Damping, damping); }

// Whether |X1| has a local maximum within `reach` of w (a sample scan).
bool hasLocalMaximumNear(double w, double damping, double reach) {
  const int n = 4000;
  for (int i = 1; i < n; ++i) {
    const double x = w - reach + 2 * reach * i / n, h = 2 * reach / n;
    const double y = dampedAmplitude(x, damping);
    if (y > dampedAmplitude(x - h, damping) && y >= dampedAmplitude(x + h, damping)) return true;
  }
  return false;
}

}  // namespace

// A followed peak that vanishes: the upper peak of the lightly damped absorber, followed
// as the absorber's damping grows until it merges into the other. Where no local maximum
// is left near it, the band's largest is taken and marked as a jump; every point is a
// local maximum of the exact response (before the jump the followed one, after it the
// global one).
TEST(PeakFollowing, AFollowedPeakThatVanishesIsReplacedByTheBandsLargest) {
  const auto P = absorber(Absorber::Damping);
  continuation::PeakFollowingOptions o;
  for (int i = 0; i <= 30; ++i) o.parameters.push_back(1e-3 * std::pow(40.0, i / 30.0));  // c2 1e-3 .. 0.04
  o.search.step = 1e-4, o.search.maxStep = 1e-2, o.search.window = 0.03, o.search.parameterTolerance = 1e-9;
  o.search.tolerance = 1e-12;
  o.bandFrom = 0.7, o.bandTo = 1.3;
  o.locateOptimum = false;
  o.sweep.from = 0.7, o.sweep.to = 1.3;
  // The upper peak at the first damping, from the exact response's scan.
  double w0 = 1.0, top = 0;
  for (int i = 0; i <= 30000; ++i) {
    const double w = 1.0 + 0.3 * i / 30000;
    if (const double a = dampedAmplitude(w, o.parameters.front()); a > top) top = a, w0 = w;
  }
  Eigen::VectorXd x0 = Eigen::VectorXd::Zero(4);
  const auto followed = continuation::followPeak(P, x0, w0, o);
  ASSERT_TRUE(followed.complete) << followed.stopReason;
  int jumps = 0, jumpAt = -1, exactVanish = -1;
  double worst = 0;
  for (std::size_t i = 0; i < followed.points.size(); ++i) {
    const auto& p = followed.points[i];
    if (p.jump) ++jumps, jumpAt = int(i);
    if (exactVanish < 0 && i > 0 && !hasLocalMaximumNear(followed.points[i - 1].frequency, p.parameter, o.search.window))
      exactVanish = int(i);
    // A local maximum of the exact response at the point's frequency.
    const double h = 1e-5;
    const double a = dampedAmplitude(p.frequency, p.parameter);
    worst = std::max(worst, std::abs(p.measure / a - 1));
    EXPECT_GE(a, dampedAmplitude(p.frequency - h, p.parameter) * (1 - 1e-9)) << i;
    EXPECT_GE(a, dampedAmplitude(p.frequency + h, p.parameter) * (1 - 1e-9)) << i;
  }
  std::printf("%zu values, %d searches, %d band sweeps; jump at c2 = %.4g (exact: the followed peak's neighbourhood "
              "loses its maximum at c2 = %.4g); amplitude against the exact response %.1e\n",
              followed.points.size(), followed.searches, followed.sweeps,
              jumpAt >= 0 ? o.parameters[std::size_t(jumpAt)] : 0.0,
              exactVanish >= 0 ? o.parameters[std::size_t(exactVanish)] : 0.0, worst);
  EXPECT_EQ(jumps, 1);
  EXPECT_EQ(jumpAt, exactVanish);
  EXPECT_GE(followed.sweeps, 1);
  // At the jump the band's largest: the exact response's global maximum over the band.
  if (jumpAt >= 0) {
    const auto& p = followed.points[std::size_t(jumpAt)];
    double global = 0;
    for (int i = 0; i <= 60000; ++i) global = std::max(global, dampedAmplitude(0.7 + 0.6 * i / 60000, p.parameter));
    EXPECT_NEAR(p.measure / global, 1.0, 1e-6);
  }
  EXPECT_LT(worst, 1e-8);
}

// How a following ends, as a type: no peak in the band at the start; the followed peak
// vanishing (the damping case above) where the band holds no other (below both
// resonances, where the response only rises towards the band's edge).
TEST(PeakFollowing, EachWayAFollowingEndsIsTyped) {
  const auto P = absorber(Absorber::Damping);
  continuation::PeakFollowingOptions o;
  for (int i = 0; i <= 30; ++i) o.parameters.push_back(1e-3 * std::pow(40.0, i / 30.0));
  o.search.step = 1e-4, o.search.maxStep = 1e-2, o.search.window = 0.03, o.search.parameterTolerance = 1e-9;
  o.search.tolerance = 1e-12;
  o.locateOptimum = false;
  o.bandFrom = o.sweep.from = 0.2, o.bandTo = o.sweep.to = 0.5;
  const auto none = continuation::followPeak(P, Eigen::VectorXd(), 0.0, o);
  EXPECT_FALSE(none.complete);
  EXPECT_TRUE(none.points.empty());
  EXPECT_EQ(none.end, continuation::PeakFollowingEnd::NoPeakAtStart) << none.stopReason;
  EXPECT_STREQ(continuation::peakFollowingEndName(none.end), "no_peak_at_start");
  // The upper peak followed as the damping merges it into the other; the band below both.
  double w0 = 1.0, top = 0;
  for (int i = 0; i <= 30000; ++i) {
    const double w = 1.0 + 0.3 * i / 30000;
    if (const double a = dampedAmplitude(w, o.parameters.front()); a > top) top = a, w0 = w;
  }
  const auto vanished = continuation::followPeak(P, Eigen::VectorXd::Zero(4), w0, o);
  EXPECT_FALSE(vanished.complete);
  EXPECT_GE(vanished.points.size(), 2u);
  EXPECT_LT(vanished.points.size(), o.parameters.size());
  EXPECT_EQ(vanished.end, continuation::PeakFollowingEnd::PeakVanished) << vanished.stopReason;
  std::printf("no peak in the band: %s (%s); the followed peak vanished after %zu values: %s (%s)\n",
              continuation::peakFollowingEndName(none.end), none.stopReason.c_str(), vanished.points.size(),
              continuation::peakFollowingEndName(vanished.end), vanished.stopReason.c_str());
}
