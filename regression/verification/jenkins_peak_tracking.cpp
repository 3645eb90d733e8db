// Verification (issue 21): the largest resonance peak of a 1-DOF oscillator
// with a Jenkins element (stiffness kt, slip force fs) under a harmonic force,
// by single-harmonic balance (AFT, 1024 samples), followed over the slip force
// from nearly free to stuck (continuation::followPeak), against the closed form
// of the describing function (here the peak moves continuously from the free
// frequency to the stuck one; the jump to another peak, where a followed one
// vanishes, is not exercised):
//   K(a) = kt / pi (beta - sin(2 beta) / 2), cos beta = 1 - 2 fs / (kt a),
//   D(a) = 4 fs (a - fs / kt) / (pi a^2)          (a > fs / kt; stuck: K = kt,
//   D = 0), a^2 [(k + K - m w^2)^2 + (c w + D)^2] = P^2   and, at a peak, its
//   w-derivative at fixed a: -2 m w (k + K - m w^2) + c (c w + D) = 0.
// Each followed peak must solve those two equations (Newton on them from the
// followed point); the smallest peak, the optimum slip force where the friction
// damps most, matches the closed form's minimum over fs. The limits: fs -> 0
// the free linear peak P / (c w) at w = 1, fs large the stuck one at sqrt(2).
// The arclength tracking of the peak condition (trackPeak) crept here at the
// sample-crossing kinks: 5000 points short of fs = 0.004 (docs/decisions.md).
// The second test continues the peak by LOCA on the peak condition with the
// response eliminated (continuation::continuePeak) over the same range, with the
// same checks, whole at 256 and 1024 samples.
#include <Tpetra_Core.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>

#include "cyclone/continuation/PeakContinuation.hpp"
#include "cyclone/continuation/PeakFollowing.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/hbm/HarmonicBalanceSystem.hpp"
#include "cyclone/hbm/JenkinsElement.hpp"
#include "cyclone/hbm/ScalarElementAdapter.hpp"

using namespace cyclone;

namespace {

constexpr double m = 1, k = 1, c = 0.01, kt = 1, P = 0.01;

// The describing function's stiffness and damping at amplitude a.
std::pair<double, double> describingFunction(double a, double fs) {
  if (a <= fs / kt) return {kt, 0.0};
  const double beta = std::acos(1 - 2 * fs / (kt * a));
  return {kt / M_PI * (beta - std::sin(2 * beta) / 2), 4 * fs * (a - fs / kt) / (M_PI * a * a)};
}

// The two peak equations at (a, w).
Eigen::Vector2d peakEquations(double a, double w, double fs) {
  const auto [K, D] = describingFunction(a, fs);
  const double s = k + K - m * w * w, d = c * w + D;
  return {a * a * (s * s + d * d) / (P * P) - 1, (-2 * m * w * s + c * d) / (m * w * w)};
}

// The closed form's peak nearest (a, w): Newton on the peak equations
// (differences).
bool closedFormPeak(double fs, double& a, double& w) {
  for (int it = 0; it < 60; ++it) {
    const Eigen::Vector2d F = peakEquations(a, w, fs);
    if (F.norm() < 1e-14) return true;
    Eigen::Matrix2d J;
    const double da = 1e-7 * a, dw = 1e-7 * w;
    J.col(0) = (peakEquations(a + da, w, fs) - peakEquations(a - da, w, fs)) / (2 * da);
    J.col(1) = (peakEquations(a, w + dw, fs) - peakEquations(a, w - dw, fs)) / (2 * dw);
    const Eigen::Vector2d step = J.partialPivLu().solve(F);
    a -= step(0), w -= step(1);
  }
  return peakEquations(a, w, fs).norm() < 1e-12;
}

// The closed form's smallest peak over fs near a computed optimum (best: its peak's
// amplitude squared, frequency and slip force): golden section on the closed-form peak,
// each from the computed optimum's peak. Returns {fs, amplitude}.
std::pair<double, double> closedFormOptimum(double bestMeasure, double bestFrequency, double bestFs) {
  auto closedAt = [&](double fs) {
    double a = std::sqrt(bestMeasure), w = bestFrequency;
    EXPECT_TRUE(closedFormPeak(fs, a, w));
    return a;
  };
  const double golden = 0.5 * (std::sqrt(5.0) - 1);
  double lo = 0.5 * bestFs, hi = 2 * bestFs;
  double x1 = hi - golden * (hi - lo), x2 = lo + golden * (hi - lo), f1 = closedAt(x1), f2 = closedAt(x2);
  while (hi - lo > 1e-10) {
    if (f1 < f2)
      hi = x2, x2 = x1, f2 = f1, x1 = hi - golden * (hi - lo), f1 = closedAt(x1);
    else
      lo = x1, x1 = x2, f1 = f2, x2 = lo + golden * (hi - lo), f2 = closedAt(x2);
  }
  const double fs = 0.5 * (lo + hi);
  return {fs, closedAt(fs)};
}

struct Oscillator {
  std::shared_ptr<hbm::HarmonicBalanceSystem> system;
  explicit Oscillator(int samples) {
    Eigen::MatrixXd M(1, 1), C(1, 1), K(1, 1);
    M << m, C << c, K << k;
    system = std::make_shared<hbm::HarmonicBalanceSystem>(M, C, K, hbm::HarmonicSet({1}), samples);
    system->addElement(std::make_shared<hbm::JenkinsElement>(kt, 1.0), Eigen::VectorXd::Ones(1));
    system->addExcitation(0, 1, P);
  }
  void setSlipForce(double fs) const {
    system->replaceElement(0,
                           std::make_shared<hbm::ScalarElementAdapter>(std::make_shared<hbm::JenkinsElement>(kt, fs)));
  }
};

continuation::PeakTrackingProblem problemOf(const Oscillator& o) {
  continuation::PeakTrackingProblem T;
  T.size = o.system->numUnknowns();
  T.residual = [o](const Eigen::VectorXd& x, double w, double fs, Eigen::VectorXd& R) {
    o.setSlipForce(fs);
    o.system->residual(x, w, R, nullptr);
  };
  T.jacobian = [o](const Eigen::VectorXd& x, double w, double fs, Eigen::MatrixXd& J) {
    o.setSlipForce(fs);
    Eigen::VectorXd R;
    o.system->residual(x, w, R, &J);
  };
  const auto& H = o.system->aft().harmonics();
  continuation::useSquaredAmplitude(T, H.cosIndex(1), H.sinIndex(1));
  return T;
}

// Every peak of `curve` against the describing function's (Newton on its two peak
// equations from the computed point), its optimum against the closed form's minimum over
// fs, the linear limits; printed with the run time, asserted at 1024 samples (the AFT's
// 1 / N^2: the stick-slip instants fall between samples, 2.4e-5 of the amplitude; the
// frequency of a flat, friction-damped top is fixed only to sqrt(that / its curvature):
// with an equivalent damping ratio of 0.1 (fs 0.04) about 1.4e-3).
void checkAgainstTheDescribingFunction(const continuation::FollowedPeakCurve& curve, const char* how, double from,
                                       double to, double seconds, const char* work, int samples) {
  double worstA = 0, worstW = 0;
  int jumps = 0;
  for (const auto& pt : curve.points) {
    double a = std::sqrt(pt.measure), w = pt.frequency;
    ASSERT_TRUE(closedFormPeak(pt.parameter, a, w)) << "fs " << pt.parameter;
    if (std::getenv("CYCLONE_VERBOSE"))
      std::printf("fs %.6g: %.8f at %.8f, closed form %.8f at %.8f%s\n", pt.parameter, std::sqrt(pt.measure),
                  pt.frequency, a, w, pt.jump ? " (jump)" : "");
    worstA = std::max(worstA, std::abs(std::sqrt(pt.measure) / a - 1));
    worstW = std::max(worstW, std::abs(pt.frequency / w - 1));
    jumps += pt.jump;
  }
  ASSERT_TRUE(curve.optimumLocated);
  const auto& best = curve.points[std::size_t(curve.optimum)];
  const auto [optimumFs, optimumA] = closedFormOptimum(best.measure, best.frequency, best.parameter);
  const auto& free = curve.points.front();
  const auto& stuck = curve.points.back();
  std::printf(
      "%zu peaks over fs %.0e .. %.1f (%d jump), %.2f s (%s)\n"
      "  against the describing function: amplitude %.1e, frequency %.1e\n"
      "  optimum: %s %.8f at fs %.6f; closed form %.8f at fs %.6f\n"
      "  limits: free %.6f at %.6f (P / (c w) = %.6f at 1), stuck %.6f at %.6f (%.6f at sqrt 2)\n",
      curve.points.size(), from, to, jumps, seconds, work, worstA, worstW, how, std::sqrt(best.measure),
      best.parameter, optimumA, optimumFs, std::sqrt(free.measure), free.frequency, P / c, std::sqrt(stuck.measure),
      stuck.frequency, P / (c * std::sqrt(2.0)));
  if (samples < 1024) return;
  EXPECT_LT(worstA, 1e-4);
  EXPECT_LT(worstW, 1e-3);
  EXPECT_NEAR(std::sqrt(best.measure) / optimumA, 1.0, 1e-4);
  EXPECT_NEAR(best.parameter / optimumFs, 1.0, 1e-2);
  // The limits (the linear peaks; a 1e-5 slip force still damps the free one a little).
  EXPECT_NEAR(std::sqrt(free.measure) / (P / c), 1.0, 5e-3);
  EXPECT_NEAR(std::sqrt(stuck.measure) / (P / (c * std::sqrt(2.0))), 1.0, 1e-4);
  EXPECT_NEAR(stuck.frequency, std::sqrt(2.0), 1e-4);
}

}  // namespace

TEST(PeakFollowing, JenkinsPeakOverTheSlipForceAgainstTheDescribingFunction) {
  // Error against run time in the AFT's samples; the checks at the finest.
  for (const int samples : {256, 1024}) {
    SCOPED_TRACE(std::to_string(samples) + " samples");
    std::printf("%d samples:\n", samples);
    const Oscillator o(samples);
    const auto T = problemOf(o);
    continuation::PeakFollowingOptions f;
    f.parameters = continuation::logarithmicValues(1e-5, 2.0, 49);
    f.bandFrom = 0.8, f.bandTo = 1.6;
    f.search.step = 1e-4, f.search.maxStep = 1e-2, f.search.window = 0.3, f.search.parameterTolerance = 1e-8;
    f.search.tolerance = 1e-12;
    f.sweep.tolerance = 1e-12;
    Timer timer;
    const auto curve = continuation::followPeak(T, Eigen::VectorXd(), 0, f);
    ASSERT_TRUE(curve.complete) << curve.stopReason;
    char work[128];
    std::snprintf(work, sizeof work, "%d sweeps, %d searches, %d Newton solves", curve.sweeps, curve.searches,
                  curve.solves);
    checkAgainstTheDescribingFunction(curve, "followed", f.parameters.front(), f.parameters.back(), timer.seconds(),
                                      work, samples);
  }
}

TEST(PeakContinuation, JenkinsPeakCurveByLocaAgainstTheDescribingFunction) {
  for (const int samples : {256, 1024}) {
    SCOPED_TRACE(std::to_string(samples) + " samples");
    std::printf("LOCA on the peak condition, %d samples:\n", samples);
    const Oscillator o(samples);
    const auto T = problemOf(o);
    // The start: the free peak at fs = 1e-5 (the closed form's, solved on the system by
    // the continuation's own search from a point of the linear curve there).
    const double fs0 = 1e-5, w0 = 1.0;
    o.setSlipForce(fs0);
    Eigen::VectorXd x0 = Eigen::VectorXd::Zero(T.size);
    x0(o.system->aft().harmonics().sinIndex(1)) = -P / c;  // the free resonance's response
    continuation::PeakContinuationOptions f;
    f.from = fs0, f.to = 2.0;
    f.tolerance = 1e-12;
    Timer timer;
    const auto curve = continuation::continuePeak(T, x0, w0, f);
    // Whole at either sample count: the curve parametrised by the phase, G's slope its
    // stencil's own (docs/decisions.md, D31; by frequency it stopped near fs =
    // 0.012 at 256 samples).
    ASSERT_TRUE(curve.complete) << curve.stopReason;
    char work[128];
    std::snprintf(work, sizeof work, "%d LOCA steps, %d Newton solves", curve.searches, curve.solves);
    checkAgainstTheDescribingFunction(curve, "continued", f.from, f.to, timer.seconds(), work, samples);
  }
}
