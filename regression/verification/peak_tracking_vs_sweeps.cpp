// Verification (issue 21): the resonance peak followed in a parameter
// (continuation::trackPeak on the harmonic balance system, H = 7 odd, 64 samples)
// against the peaks of independently traced frequency curves. A 2-DOF chain with a
// hardening cubic spring from its second mass to ground, excited at the first; the
// parameter is the force level: the peak moves up in frequency and bends over. At
// five force levels the frequency curve is traced by the predictor-corrector over the
// whole band (it locates the maxima of the second mass's first-harmonic amplitude on
// the path), and the tracked peak is corrected at the same level: amplitude and
// frequency must agree to that location's tolerance. (A friction element's Jacobian
// jumps where a stick-slip instant crosses a time sample, and so does the peak
// condition: followed that way the friction peak creeps; docs/decisions.md. The second
// test continues a friction peak by LOCA on the reduced peak condition, continuePeak.)
#include <Tpetra_Core.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>

#include "cyclone/continuation/NewtonSolve.hpp"
#include "cyclone/continuation/PeakContinuation.hpp"
#include "cyclone/continuation/PeakTracking.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/hbm/HarmonicBalanceSystem.hpp"
#include "cyclone/hbm/CubicSpring.hpp"
#include "cyclone/hbm/JenkinsElement.hpp"

using namespace cyclone;

namespace {

constexpr double force = 0.1;

// The chain; the parameter scales the excitation. With `friction`, a Jenkins element
// (stiffness 0.5, slip force 0.02) from the second mass to ground instead of the cubic
// spring, harmonics 1, 3, 5 and 256 samples.
struct Chain {
  std::shared_ptr<hbm::HarmonicBalanceSystem> system;
  explicit Chain(bool friction = false) {
    Eigen::MatrixXd M(2, 2), K(2, 2);
    M << 1.0, 0.0, 0.0, 0.5;
    K << 2.0, -1.0, -1.0, 1.0;
    system = std::make_shared<hbm::HarmonicBalanceSystem>(M, 0.02 * K, K, hbm::HarmonicSet::odd(friction ? 5 : 7),
                                                          friction ? 256 : 64);
    if (friction)
      system->addElement(std::make_shared<hbm::JenkinsElement>(0.5, 0.02), Eigen::Vector2d(0, 1));
    else
      system->addElement(std::make_shared<hbm::CubicSpring>(0.5), Eigen::Vector2d(0, 1));
    system->addExcitation(0, 1, force);
  }
};

continuation::PeakTrackingProblem trackingProblem(const Chain& c) {
  continuation::PeakTrackingProblem P;
  P.size = c.system->numUnknowns();
  P.residual = [c](const Eigen::VectorXd& x, double w, double p, Eigen::VectorXd& R) {
    c.system->residual(x, w, R, nullptr, p);
  };
  P.jacobian = [c](const Eigen::VectorXd& x, double w, double p, Eigen::MatrixXd& J) {
    Eigen::VectorXd R;
    c.system->residual(x, w, R, &J, p);
  };
  const int nc = c.system->numCoefficients();
  const auto& H = c.system->aft().harmonics();
  continuation::useSquaredAmplitude(P, nc + H.cosIndex(1), nc + H.sinIndex(1));  // the second mass
  return P;
}

// The frequency curve at force level p over [0.2, 2] rad/s, started at its low end.
continuation::ContinuationProblem frequencyCurve(const Chain& c, double p, const continuation::PeakTrackingProblem& P) {
  continuation::ContinuationProblem f;
  f.size = P.size;
  f.residual = [c, p](const Eigen::VectorXd& x, double w, Eigen::VectorXd& R) {
    c.system->residual(x, w, R, nullptr, p);
  };
  f.jacobian = [c, p](const Eigen::VectorXd& x, double w, Eigen::MatrixXd& J) {
    Eigen::VectorXd R;
    c.system->residual(x, w, R, &J, p);
  };
  f.measure = P.measure;
  return f;
}

struct SweptPeak {
  double w = 0, m = 0;
  Eigen::VectorXd x;
};

SweptPeak sweptPeak(const Chain& c, double p, const continuation::PeakTrackingProblem& P) {
  const auto curve = frequencyCurve(c, p, P);
  continuation::ContinuationOptions o;
  o.from = 0.2, o.to = 2.0, o.tolerance = 1e-11;
  Eigen::VectorXd x0 = c.system->linearizedSolution(o.from, p);
  continuation::solveNewton(curve, x0, o.from, 1e-11);
  const auto branch = continuation::traceBranch(curve, x0, o);
  EXPECT_TRUE(branch.finished) << "force level " << p << ": " << branch.stopReason;
  SweptPeak best;
  for (const auto& pt : branch.points)
    if (const double m = P.measure(pt.x); m > best.m) best = {pt.parameter, m, pt.x};
  return best;
}

}  // namespace

TEST(PeakTracking, HardeningPeakAgainstSweptFrequencyCurves) {
  const Chain c;
  const auto P = trackingProblem(c);
  Timer timer;
  const auto start = sweptPeak(c, 0.2, P);
  continuation::ContinuationOptions o;
  o.from = 0.2, o.to = 3.0, o.tolerance = 1e-10;
  const auto curve = continuation::trackPeak(P, start.x, start.w, o);
  const double trackSeconds = timer.seconds();
  ASSERT_TRUE(curve.finished) << curve.stopReason;
  std::printf("peak tracked in the force level 0.2 -> 3: %zu points, %.2f s; amplitude %.5f -> %.5f, %.4f -> %.4f "
              "rad/s\n",
              curve.points.size(), trackSeconds, std::sqrt(curve.points.front().measure),
              std::sqrt(curve.points.back().measure), curve.points.front().frequency, curve.points.back().frequency);

  const auto extended = continuation::peakCondition(P);
  double worstM = 0, worstW = 0, sweepSeconds = 0;
  for (double p : {0.3, 0.6, 1.0, 1.8, 2.7}) {
    timer.restart();
    const auto ref = sweptPeak(c, p, P);
    sweepSeconds += timer.seconds();
    // The tracked curve at exactly p: its nearest point corrected there.
    std::size_t near = 0;
    for (std::size_t i = 0; i < curve.points.size(); ++i)
      if (std::abs(curve.points[i].parameter - p) < std::abs(curve.points[near].parameter - p)) near = i;
    Eigen::VectorXd y(P.size + 1);
    y.head(P.size) = curve.points[near].x;
    y(P.size) = curve.points[near].frequency;
    const auto newton = continuation::solveNewton(extended, y, p, 1e-10);
    ASSERT_TRUE(newton.converged) << "force level " << p;
    const double m = P.measure(Eigen::VectorXd(y.head(P.size))), w = y(P.size);
    const double em = std::abs(m / ref.m - 1), ew = std::abs(w / ref.w - 1);
    worstM = std::max(worstM, em), worstW = std::max(worstW, ew);
    std::printf("force level %.2f: swept peak %.6f at %.6f rad/s, tracked %.6f at %.6f: %.1e, %.1e\n", p,
                std::sqrt(ref.m), ref.w, std::sqrt(m), w, em, ew);
  }
  std::printf("five swept curves %.2f s against one tracked peak curve %.2f s\n", sweepSeconds, trackSeconds);
  // The sweep locates its maxima to 1e-5 of the steps around them (at most about 4e-6 of the
  // frequency here); the amplitude's error is second order in that.
  EXPECT_LT(worstW, 1e-6);
  EXPECT_LT(worstM, 1e-9);
}

// The same check for friction by LOCA on the peak condition (continuation::continuePeak):
// the chain with a Jenkins element, the force level 0.05 -> 5 (stuck to mostly slipping:
// the peak moves from the stuck resonance down towards the free one), five continued
// points against frequency curves traced at their levels. The continued peak is the zero
// of a phase stencil, h = 0.1 rad: its bias on a linear top, h^2 c^2 / 12 in ln w with c
// the damping ratio's double (0.02 x the stiffness here: about 0.02 at the resonance),
// is 3e-7 in frequency and 1e-11 in the measure. Both are peaks of the same sampled system,
// each to its method's resolution of a top the sampled stick-slip instants make piecewise
// smooth: at 256 samples the 1-DOF Jenkins peak found by a search is off the describing
// function by 4.7e-4 in amplitude (jenkins_peak_tracking), 1e-3 in the squared amplitude
// measured here; a friction-damped top fixes its frequency only to sqrt(that / its
// curvature), sqrt(5e-4 / 100) = 2.2e-3 at an equivalent damping ratio of 0.1 (3e-3
// asserted). Measured: 1.3e-4 and 6.5e-4 in the stick-slip transition, 1e-6 slipping.
TEST(PeakContinuation, FrictionPeakByLocaAgainstSweptFrequencyCurves) {
  const Chain c(true);
  const auto P = trackingProblem(c);
  Timer timer;
  const auto start = sweptPeak(c, 0.05, P);
  continuation::PeakContinuationOptions o;
  o.from = 0.05, o.to = 5.0, o.tolerance = 1e-11;
  const auto curve = continuation::continuePeak(P, start.x, start.w, o);
  const double continuedSeconds = timer.seconds();
  ASSERT_TRUE(curve.complete) << curve.stopReason;
  ASSERT_GE(curve.points.size(), 5u);
  std::printf("peak continued in the force level 0.05 -> 5: %zu points, %d solves, %.2f s; amplitude %.5f -> %.5f, "
              "%.4f -> %.4f rad/s\n",
              curve.points.size(), curve.solves, continuedSeconds, std::sqrt(curve.points.front().measure),
              std::sqrt(curve.points.back().measure), curve.points.front().frequency, curve.points.back().frequency);
  double worstM = 0, worstW = 0, sweepSeconds = 0;
  for (int k = 0; k < 5; ++k) {
    const auto& a = curve.points[std::size_t(k * (curve.points.size() - 1) / 4)];
    timer.restart();
    const auto ref = sweptPeak(c, a.parameter, P);
    sweepSeconds += timer.seconds();
    const double em = std::abs(a.measure / ref.m - 1), ew = std::abs(a.frequency / ref.w - 1);
    worstM = std::max(worstM, em), worstW = std::max(worstW, ew);
    std::printf("force level %.4f: swept peak %.6f at %.6f rad/s, continued %.6f at %.6f: %.1e, %.1e\n", a.parameter,
                std::sqrt(ref.m), ref.w, std::sqrt(a.measure), a.frequency, em, ew);
  }
  std::printf("five swept curves %.2f s against one continued peak curve %.2f s\n", sweepSeconds, continuedSeconds);
  EXPECT_LT(worstW, 3e-3);
  EXPECT_LT(worstM, 1e-3);
}
