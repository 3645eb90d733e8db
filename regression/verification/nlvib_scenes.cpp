// Verification: NLvib's examples 02, 03 and 07 from their scene files. Each
// curve is traced as `cyclone run` traces it (response::traceForcedResponse: the
// first point found from rest, then arclength continuation); a point of it is
// checked by Hill's method and confirmed by time integration of the same system
// started on its periodic solution: were that solution not a stable periodic
// motion of the system, the integration would drift away from it.
#include <Tpetra_Core.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "cyclone/continuation/NewtonSolve.hpp"
#include "cyclone/hbm/HarmonicRefinement.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/hbm/HillStability.hpp"
#include "cyclone/hbm/TimeIntegration.hpp"
#include "cyclone/response/ForcedResponseTrace.hpp"
#include "cyclone/scenes/ForcedResponseScene.hpp"

using namespace cyclone;

namespace {

struct TracedScene {
  response::ForcedResponseSetup setup;
  response::StartingPoint start;
  continuation::Branch branch;
  double seconds = 0;
};

TracedScene traceScene(const std::string& file) {
  Timer timer;
  TracedScene t;
  t.setup = scenes::loadForcedResponseScene(std::string(CYCLONE_SCENE_DIR "/") + file);
  t.start = response::findStartingPoint(t.setup);
  t.branch = response::traceForcedResponse(t.setup, t.start);
  t.seconds = timer.seconds();
  std::printf("%s: first point by %s (%.2f s); %zu points, %s (%.1f s)\n", file.c_str(), t.start.method.c_str(),
              t.start.seconds, t.branch.points.size(), t.branch.stopReason.c_str(), t.seconds);
  return t;
}

/// The point of largest first-harmonic amplitude of a DOF.
std::size_t peakIndex(const TracedScene& t, int dof) {
  const auto& sys = *t.setup.system;
  std::size_t peak = 0;
  for (std::size_t i = 0; i < t.branch.points.size(); ++i)
    if (sys.amplitude(t.branch.points[i].x, dof, 1) > sys.amplitude(t.branch.points[peak].x, dof, 1)) peak = i;
  return peak;
}

/// Newmark from the periodic solution of a branch point; prints and returns the
/// relative difference of the first-harmonic amplitude of `dof`.
struct Confirmation {
  hbm::SteadyState steady;
  double hb = 0, ti = 0, relative = 0, seconds = 0;
};

Confirmation integrateFrom(const TracedScene& t, const continuation::BranchPoint& pt, int dof, int stepsPerPeriod,
                           int maxPeriods = 2000) {
  const auto& sys = *t.setup.system;
  Timer timer;
  hbm::TimeIntegrationOptions options;
  options.stepsPerPeriod = stepsPerPeriod;
  options.maxPeriods = maxPeriods;
  Confirmation c;
  c.steady = hbm::integrateToSteadyState(sys, pt.parameter, pt.x, options);
  c.seconds = timer.seconds();
  c.hb = sys.amplitude(pt.x, dof, 1);
  c.ti = sys.amplitude(c.steady.coefficients, dof, 1);
  c.relative = std::abs(c.ti / c.hb - 1);
  std::printf("  time integration, %d steps per period: |x1| of DOF %d %.6f against HB %.6f, relative difference "
              "%.1e; %d periods (%s, period change %.1e), %.2f s\n",
              stepsPerPeriod, dof + 1, c.ti, c.hb, c.relative, c.steady.periods,
              c.steady.converged ? "periodic" : "not periodic", c.steady.periodChange, c.seconds);
  return c;
}

hbm::FloquetExponents hill(const TracedScene& t, const continuation::BranchPoint& pt, const char* what, int dof) {
  const auto fl = hbm::hillStability(*t.setup.system, pt.x, pt.parameter);
  std::printf("  %s: W = %.5f, |x1| of DOF %d = %.6f, %s by Hill's method (max Re %.2e)\n", what, pt.parameter,
              dof + 1, t.setup.system->amplitude(pt.x, dof, 1), fl.stable ? "stable" : "unstable", fl.maxRealPart);
  return fl;
}

/// The first-harmonic amplitude of `dof` at the same frequency with harmonics 0..H:
/// the scene's system rebuilt, Newton from the point's coefficients (zero for the
/// added harmonics). Measures the truncation of the scene's harmonic balance.
double amplitudeWithHarmonics(const TracedScene& t, const continuation::BranchPoint& pt, int dof, int H) {
  const auto& s = *t.setup.system;
  const auto refined = hbm::withHarmonics(s, hbm::HarmonicSet::upTo(H), std::max(s.aft().numSamples(), 4 * H + 1));
  const auto& r = *refined;
  Eigen::VectorXd X = hbm::transferCoefficients(pt.x, s.numDofs(), s.aft().harmonics(), r.aft().harmonics());
  const auto problem = response::continuationProblem(r, response::ForcedResponseSetup::Parameter::Omega);
  EXPECT_TRUE(continuation::solveNewton(problem, X, pt.parameter, t.setup.continuation.tolerance, 100).converged)
      << "H = " << H;
  const double a = r.amplitude(X, dof, 1);
  std::printf("  harmonic balance with H = %d at the same W: |x1| of DOF %d %.6f (relative change %.1e)\n", H,
              dof + 1, a, std::abs(a / s.amplitude(pt.x, dof, 1) - 1));
  return a;
}

/// A point Hill's method finds unstable: the time integration started on it does not
/// stay there (it reaches another motion, or none that repeats with the period).
void expectLeftByTimeIntegration(const TracedScene& t, const continuation::BranchPoint& pt, int dof, const char* what) {
  EXPECT_FALSE(hill(t, pt, what, dof).stable);
  const auto away = integrateFrom(t, pt, dof, 1024, 600);
  EXPECT_TRUE(!away.steady.converged || away.relative > 1e-2);
}

/// A point Hill's method finds stable: the time integration stays on it, at two step
/// counts (their difference is the time-step error, 2nd order), and the rest of the
/// difference is the truncation of the harmonic balance (measured with 2H harmonics).
void expectConfirmedByTimeIntegration(const TracedScene& t, const continuation::BranchPoint& pt, int dof,
                                      const char* what, double tolerance) {
  EXPECT_TRUE(hill(t, pt, what, dof).stable);
  const auto coarse = integrateFrom(t, pt, dof, 1024);
  const auto fine = integrateFrom(t, pt, dof, 4096);
  ASSERT_TRUE(coarse.steady.converged && fine.steady.converged);
  const double refined = amplitudeWithHarmonics(t, pt, dof, 2 * t.setup.system->aft().harmonics().maxHarmonic());
  const double againstRefined = std::abs(fine.ti / refined - 1);
  std::printf("  time integration (4096 steps) against HB with 2H: relative difference %.1e\n", againstRefined);
  EXPECT_LT(std::abs(coarse.ti / fine.ti - 1), 1e-4);  // the time step: 2nd order, (W dt)^2 ~ 4e-5 at 1024 steps
  EXPECT_LT(againstRefined, 0.2 * fine.relative);      // the rest is the truncation in H
  EXPECT_LT(coarse.relative, tolerance);
  EXPECT_LT(fine.relative, tolerance);
}

}  // namespace

TEST(NlvibScenes, Example02PeakConfirmedByTimeIntegration) {
  const auto t = traceScene("nlvib_02.yaml");
  ASSERT_TRUE(t.branch.finished) << t.branch.stopReason;
  const auto& pt = t.branch.points[peakIndex(t, 0)];
  EXPECT_TRUE(hill(t, pt, "peak", 0).stable);
  const auto c = integrateFrom(t, pt, 0, 2048);
  ASSERT_TRUE(c.steady.converged);
  EXPECT_LT(c.relative, 1e-4);
}

// Example 03: a unilateral spring (k = 100, gap 1) on DOF 1, H = 21, W = 0.8 -> 0.5.
// NLvib's amplitude is the first harmonic of DOF 2. Its own shooting analysis finds
// the top of the curve beyond a period-doubling bifurcation (unstable) and stable
// period-one motion near W = 0.635; so the peak is shown unstable (Hill, and the
// time integration leaving it) and the stable point near 0.635 is confirmed.
TEST(NlvibScenes, Example03UnstablePeakAndStablePointByTimeIntegration) {
  const auto t = traceScene("nlvib_03.yaml");
  ASSERT_TRUE(t.branch.finished) << t.branch.stopReason;
  const int dof = 1;
  expectLeftByTimeIntegration(t, t.branch.points[peakIndex(t, dof)], dof, "peak");
  std::size_t near = 0;
  for (std::size_t i = 0; i < t.branch.points.size(); ++i)
    if (std::abs(t.branch.points[i].parameter - 0.635) < std::abs(t.branch.points[near].parameter - 0.635)) near = i;
  // H = 21 against a unilateral spring of stiffness 100: the truncation is 8e-4 here.
  expectConfirmedByTimeIntegration(t, t.branch.points[near], dof, "stable point near W = 0.635", 2e-3);
}

// Example 07: Jenkins elements (k = 20, slip force 1) on DOF 1 and between DOFs 1-2,
// cubic springs on DOF 2 and between DOFs 2-3, a unilateral spring (1, gap 0.25) on
// DOF 3; H = 7, W = 0.5 -> 2. Newton from the linear solution stagnates here; the
// first point comes from rest (response::findStartingPoint).
TEST(NlvibScenes, Example07StartsFromRestAndPeaksCheckedByTimeIntegration) {
  const auto t = traceScene("nlvib_07.yaml");
  ASSERT_TRUE(t.branch.finished) << t.branch.stopReason;
  EXPECT_EQ(t.start.method, "Newton from rest");
  {  // The way that failed: Newton from the linear solution without the elements.
    const auto problem = response::continuationProblem(*t.setup.system, t.setup.parameter);
    Eigen::VectorXd x = t.setup.system->linearSolution(t.setup.continuation.from), R;
    Timer timer;
    const bool converged =
        continuation::solveNewton(problem, x, t.setup.continuation.from, t.setup.continuation.tolerance, 100).converged;
    problem.residual(x, t.setup.continuation.from, R);
    std::printf("  Newton from the linear solution instead: %s, |R| = %.3f (%.2f s)\n",
                converged ? "converged" : "stagnated", R.norm(), timer.seconds());
    EXPECT_FALSE(converged);
  }
  // The top of DOF 3 (the gap side) is unstable; the resonance peak of the excited DOF 2 is stable.
  expectLeftByTimeIntegration(t, t.branch.points[peakIndex(t, 2)], 2, "peak of DOF 3");
  // H = 7 against stick-slip and contact: the truncation is 2.5e-3 here.
  expectConfirmedByTimeIntegration(t, t.branch.points[peakIndex(t, 1)], 1, "peak of DOF 2", 5e-3);
}

// The last way to a first point: example 03 started at W = 0.65, inside the contact
// regime, where Newton stagnates both from rest and from the linear solution; the
// response is followed from rest as the excitation grows (through its folds).
TEST(NlvibScenes, FirstPointByExcitationRampWhereNewtonStagnates) {
  auto setup = scenes::loadForcedResponseScene(CYCLONE_SCENE_DIR "/nlvib_03.yaml");
  setup.continuation.from = 0.65;
  const auto start = response::findStartingPoint(setup);
  std::printf("nlvib_03.yaml from W = 0.65: first point by %s (%.2f s), |x1| of DOF 2 = %.6f\n",
              start.method.c_str(), start.seconds, start.x.size() ? setup.system->amplitude(start.x, 1, 1) : 0.0);
  ASSERT_EQ(start.method.rfind("ramp of the excitation from rest", 0), 0u) << start.method;
  Eigen::VectorXd R;
  setup.system->residual(start.x, 0.65, R, nullptr);
  EXPECT_LT(R.norm(), setup.continuation.tolerance);
}

// Where no first point converges at the start of the range, the curve is traced from
// the other end (the default disc at H = 5 has no start near its peak, docs/scenes.md).
// Example 02 with its start refused: the curve from the end of the range reaches the
// start through both folds, and its peak and folds are those of the curve traced
// from the start.
TEST(NlvibScenes, ACurveWithoutAStartIsTracedFromTheEnd) {
  auto forward = traceScene("nlvib_02.yaml");
  ASSERT_TRUE(forward.branch.finished) << forward.branch.stopReason;
  auto setup = scenes::loadForcedResponseScene(CYCLONE_SCENE_DIR "/nlvib_02.yaml");
  const response::StartingPoint refused{Eigen::VectorXd(), "refused by the test", 0.0};
  const auto branch = response::traceForcedResponse(setup, refused);
  std::printf("nlvib_02.yaml without a start: %zu points, %s\n", branch.points.size(), branch.stopReason.c_str());
  ASSERT_TRUE(branch.finished) << branch.stopReason;
  EXPECT_NE(branch.stopReason.find("refused by the test"), std::string::npos) << branch.stopReason;
  EXPECT_NE(branch.stopReason.find("from the end of the range"), std::string::npos) << branch.stopReason;
  // Traced downwards: from the end of the range to its start.
  EXPECT_NEAR(branch.points.front().parameter, setup.continuation.to, 1e-12);
  EXPECT_NEAR(branch.points.back().parameter, setup.continuation.from, 1e-12);
  // The peak of the scene's response measure (the first output DOF's max |x(t)|),
  // which both traces locate on their paths.
  const auto measure = response::continuationProblem(setup).measure;
  ASSERT_TRUE(bool(measure));
  auto peakOf = [&measure](const continuation::Branch& b) {
    double best = 0;
    for (const auto& pt : b.points) best = std::max(best, measure(pt.x));
    return best;
  };
  auto foldsOf = [](const continuation::Branch& b) {
    int folds = 0;
    for (std::size_t i = 2; i < b.points.size(); ++i) {
      const double d1 = b.points[i - 1].parameter - b.points[i - 2].parameter;
      const double d2 = b.points[i].parameter - b.points[i - 1].parameter;
      folds += (d1 > 0) != (d2 > 0);
    }
    return folds;
  };
  const double up = peakOf(forward.branch), down = peakOf(branch);
  std::printf("  peak max|x(t)| of the output DOF: from the start %.10f, from the end %.10f; folds %d and %d\n", up, down,
              foldsOf(forward.branch), foldsOf(branch));
  EXPECT_NEAR(down / up, 1.0, 1e-7);
  EXPECT_EQ(foldsOf(branch), foldsOf(forward.branch));
}
