// Two resonances of similar height in one DOF's response, whose order flips as the
// harmonics grow: harmonics by an error target must follow both and head with the larger
// converged one. DOF 0 is linear (k = 4, its resonance near 2.04 rad/s), DOF 1 hammers
// against a unilateral spring (kn = 50, pressed shut by 0.1; k = 1, its resonance near
// 1.6 rad/s), coupled by a spring of 0.5 and both driven (2.6 and 0.3 cos W t); the output
// is DOF 1. With H = 1 the hammering peak is the larger (12.78 against 12.08); the
// harmonics take energy out of it (12.2) and the linear one rises (13.2), so a check that
// followed only the first curve's largest peak headed with the smaller one (the issue's
// "wrong headline"). The references, independent of the check: the curve traced with H =
// 16 and 1024 samples (its own start and trace, no checks), its largest point; and Newmark
// (4096 steps a period) from the headline's solution to the periodic steady state.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>

#include "cyclone/core/Log.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/hbm/HarmonicRefinement.hpp"
#include "cyclone/hbm/PeakMagnitude.hpp"
#include "cyclone/hbm/TimeIntegration.hpp"
#include "cyclone/hbm/UnilateralSpring.hpp"
#include "cyclone/response/ForcedResponse.hpp"

using namespace cyclone;

namespace {

std::unique_ptr<hbm::HarmonicBalanceSystem> twoResonances(int H, int samples) {
  Eigen::MatrixXd M = Eigen::MatrixXd::Identity(2, 2), K(2, 2), C = Eigen::MatrixXd::Zero(2, 2);
  K << 4.0, -0.5, -0.5, 1.0;
  C(0, 0) = 0.05, C(1, 1) = 0.1;
  auto sys = std::make_unique<hbm::HarmonicBalanceSystem>(M, C, K, hbm::HarmonicSet::upTo(H), samples);
  Eigen::VectorXd normal(2);
  normal << 0.0, 1.0;
  sys->addElement(std::make_shared<hbm::UnilateralSpring>(50.0, 0.0), normal);
  sys->addStaticLoad(1, 0.1);
  sys->addExcitation(0, 1, 2.6);
  sys->addExcitation(1, 1, 0.3);
  return sys;
}

response::ForcedResponseSetup curveSetup(int H, int samples) {
  response::ForcedResponseSetup setup;
  setup.system = twoResonances(H, samples);
  setup.outputDofs = {1, 0};
  setup.continuation.from = 0.5, setup.continuation.to = 2.5;
  setup.stability = response::ForcedResponseSetup::Stability::Never;
  return setup;
}

}  // namespace

TEST(TwoResonanceHeadline, EveryPeakFollowedAndTheLargestConvergedHeads) {
  log::setQuiet(true);
  constexpr double kTolerance = 0.01;

  // The premise: with H = 1 the hammering resonance is the curve's largest point.
  Timer timer;
  auto first = curveSetup(1, 64);
  first.harmonicsCheckTo = -1;
  const auto h1 = response::solveForcedResponse(first);
  ASSERT_TRUE(h1.branch.finished) << h1.branch.stopReason;
  const double h1Seconds = timer.seconds();

  // Harmonics by an error target from H = 1.
  timer.restart();
  auto setup = curveSetup(1, 64);
  setup.harmonicsTolerance = kTolerance;
  setup.harmonicsCheckTo = 20;
  const auto target = response::solveForcedResponse(setup);
  const double targetSeconds = timer.seconds();
  ASSERT_GE(target.harmonicsTarget.reached, 0) << target.harmonicsTarget.text;
  const auto& headline = target.harmonicsCheck.converged;
  ASSERT_TRUE(headline.found) << target.harmonicsCheck.text;
  ASSERT_EQ(target.otherPeakChecks.size(), 1u) << target.harmonicsTarget.text;
  const auto& other = target.otherPeakChecks.front().converged;
  ASSERT_TRUE(other.found) << target.otherPeakChecks.front().text;
  // Two distinct resonances, the larger converged one heading; with H = 1 the other was
  // the curve's largest point (the premise: without following every peak the headline
  // would have been the other one).
  EXPECT_GT(std::abs(headline.hz / other.hz - 1), 0.1);
  EXPECT_GT(headline.value, other.value);
  EXPECT_LT(std::abs(h1.peakOmega - 2 * M_PI * other.hz), std::abs(h1.peakOmega - 2 * M_PI * headline.hz));

  // Reference 1: the curve with H = 16, traced on its own.
  timer.restart();
  auto fine = curveSetup(16, 1024);
  fine.harmonicsCheckTo = -1;
  const auto reference = response::solveForcedResponse(fine);
  const double referenceSeconds = timer.seconds();
  ASSERT_TRUE(reference.branch.finished) << reference.branch.stopReason;
  const double curveError = std::abs(headline.value / reference.peak - 1);
  EXPECT_LE(curveError, kTolerance);
  EXPECT_NEAR(headline.hz * 2 * M_PI, reference.peakOmega, 5e-3 * reference.peakOmega);

  // Reference 2: Newmark from the headline's solution, on its own harmonics and samples.
  const auto system = twoResonances(1, 64);
  const auto headSystem = hbm::withHarmonics(*system, hbm::HarmonicSet(headline.harmonics), headline.samples);
  hbm::TimeIntegrationOptions ti;
  ti.stepsPerPeriod = 4096;
  timer.restart();
  const auto steady = hbm::integrateToSteadyState(*headSystem, 2 * M_PI * headline.hz, headline.x, ti);
  const double newmarkSeconds = timer.seconds();
  ASSERT_TRUE(steady.converged);
  const int nc = headSystem->numCoefficients();
  const double newmark =
      hbm::peakMagnitude(headSystem->aft().harmonics(), Eigen::VectorXd(steady.coefficients.segment(nc, nc)));
  const double newmarkError = std::abs(headline.value / newmark - 1);
  EXPECT_LE(newmarkError, kTolerance);

  std::printf("H = 1 curve: largest %.5f at W = %.4f (%.2f s)\n", h1.peak, h1.peakOmega, h1Seconds);
  for (const auto* check : {&target.harmonicsCheck, &target.otherPeakChecks.front()}) {
    std::printf("peak followed from W = %.4f:\n", 2 * M_PI * check->levels.front().startHz);
    for (const auto& level : check->levels)
      std::printf("  H %2d (%4d samples): %.5f at W = %.5f, against the H = 16 curve's largest %+.2e, %.3f s\n",
                  level.maxHarmonic, level.samples, level.peak.value, 2 * M_PI * level.peak.parameter,
                  level.peak.value / reference.peak - 1, level.seconds);
  }
  std::printf("headline %.5f at W = %.5f with H = %d (%.2f s in all); H = 16 curve's largest %.5f at W = %.5f "
              "(%.2f s): %.2e; Newmark from the headline's solution %.5f (%.2f s): %.2e\n",
              headline.value, 2 * M_PI * headline.hz, headline.maxHarmonic, targetSeconds, reference.peak,
              reference.peakOmega, referenceSeconds, curveError, newmark, newmarkSeconds, newmarkError);
}
