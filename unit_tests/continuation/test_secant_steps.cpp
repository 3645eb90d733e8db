// Secant steps over a stair of kinks (PredictorCorrector.cpp, switchPredictor): a
// resonance whose stiffness is piecewise linear in the amplitude, with a kink every
// delta of amplitude (as a sampled contact law has one wherever a contact instant
// crosses a time sample). The tangent turns at each kink by about as much at any step,
// so the tangent's step control holds the step at a corner's size over the whole
// resonance; the secant steps cross it in a fraction of the points, every point a
// solution, and the curve's highest point is the closed form's.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "cyclone/continuation/ArclengthContinuation.hpp"
#include "KinkedOscillator.hpp"

using namespace cyclone;
using test_support::KinkedOscillator;


TEST(SecantSteps, StairOfKinksCrossedInAFractionOfThePointsToTheClosedFormPeak) {
  const KinkedOscillator osc;
  const auto problem = osc.problem();
  continuation::ContinuationOptions o;
  o.from = 0.9, o.to = 1.1;
  o.maxSteps = 20000;
  auto tangentOnly = o;
  tangentOnly.secantOverKinks = false;
  const auto byTangent = continuation::traceBranch(problem, Eigen::VectorXd::Zero(2), tangentOnly);
  const auto bySecant = continuation::traceBranch(problem, Eigen::VectorXd::Zero(2), o);
  const double reference = osc.peakAmplitude();
  auto highest = [](const continuation::Branch& b) {
    double top = 0;
    for (const auto& pt : b.points) top = std::max(top, pt.x.norm());
    return top;
  };
  std::printf("closed-form peak %.8f; tangent steps: %zu points, peak %.8f; secant: %zu points (%ld secant steps), "
              "peak %.8f\n",
              reference, byTangent.points.size(), highest(byTangent), bySecant.points.size(),
              bySecant.statistics.secantSteps, highest(bySecant));
  std::printf("tangent: %s\nsecant: %s\n", byTangent.stopReason.c_str(), bySecant.stopReason.c_str());
  ASSERT_TRUE(bySecant.finished) << bySecant.stopReason;
  EXPECT_EQ(byTangent.statistics.secantSteps, 0);
  EXPECT_GT(bySecant.statistics.secantSteps, 0);
  for (const auto& pt : bySecant.points) {
    Eigen::VectorXd F;
    problem.residual(pt.x, pt.parameter, F);
    EXPECT_LT(F.norm(), 1e-9);
  }
  EXPECT_NEAR(highest(bySecant) / reference, 1.0, 1e-5);
  EXPECT_NEAR(highest(byTangent) / reference, 1.0, 1e-5);
  EXPECT_LT(3 * bySecant.points.size(), byTangent.points.size());
}
