// The default disc's headline peak, converged in the harmonics by an error target
// (1 %: the demo's harmonics: auto), against an independently traced curve with two
// harmonics more: a new harmonic balance (H + 2, its own start and arclength trace over
// a band around the peak, no harmonics check), whose peak must lie within the target of
// the headline. The demo's disc: 24 sectors, mesh size 6, 10 000 rpm, EO 3, 43 shroud
// pairs at 500 N preload, 20 N at mid-blade. Slow label (about 5 min).
#include <Tpetra_Core.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "cyclone/core/Log.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/disc/DiscForcedResponse.hpp"
#include "cyclone/mesh/ShroudedSectorGenerator.hpp"
#include "DemoDisc.hpp"

using namespace cyclone;

TEST(DiscHarmonicsTarget, ConvergedPeakMeetsACurveWithTwoHarmonicsMore) {
  log::setQuiet(true);
  mesh::ShroudedSectorParameters p;  // the demo's disc
  p.meshSize = 6.0;
  const auto mesh = mesh::generateShroudedSector(p);
  const disc::DiscModelSpec models = demo_disc::demoDiscModels(p);
  const disc::DiscResponseSpec spec = demo_disc::demoDiscResponse(1);
  constexpr int kMax = 7, kAbove = 2;
  constexpr double kTolerance = 0.01;
  std::vector<int> all;
  for (int h = 0; h <= kMax + kAbove; ++h) all.push_back(h);
  const auto reduced = disc::buildDiscReducedModels(mesh, models, disc::nodalDiametersFor(p.sectors, 3, all),
                                                    "disc_harmonics_target_models", Tpetra::getDefaultComm());

  Timer timer;
  disc::DiscSweepOptions sweep;
  sweep.stability = response::ForcedResponseSetup::Stability::Never;
  sweep.harmonicsTolerance = kTolerance;
  sweep.harmonicsCheckTo = kMax;
  const auto target = disc::solveDiscForcedResponse(mesh, reduced, spec, sweep);
  const double targetSeconds = timer.seconds();
  ASSERT_TRUE(target.headline.found());
  ASSERT_TRUE(target.headline.converged()) << target.headline.text;
  const int H = target.headline.peak.maxHarmonic;
  const double peak = target.headline.peak.value, hz = target.headline.peak.hz;
  EXPECT_EQ(target.curve.harmonicsTarget.reached, H);
  EXPECT_TRUE(target.curve.harmonicsTarget.retraced);

  // H + 2 from scratch over a band around that peak.
  timer.restart();
  disc::DiscResponseSpec above = spec;
  above.harmonics.clear();
  for (int h = 0; h <= H + kAbove; ++h) above.harmonics.push_back(h);
  disc::DiscSweepOptions band;
  band.stability = response::ForcedResponseSetup::Stability::Never;
  band.harmonicsCheckTo = -1;
  band.fromHz = hz - 15, band.toHz = hz + 15;
  const auto independent = disc::solveDiscForcedResponse(mesh, reduced, above, band);
  const double aboveSeconds = timer.seconds();
  ASSERT_TRUE(independent.curve.branch.finished) << independent.curve.branch.stopReason;
  const double abovePeak = independent.curve.peak, aboveHz = independent.curve.peakOmega / (2 * M_PI);
  std::printf("harmonics by a 1 %% target: H = %d, peak %.6f mm at %.3f Hz (%.1f s, the curve traced whole with it); "
              "H = %d traced over %.1f..%.1f Hz: %zu points, peak %.6f mm at %.3f Hz (%.1f s); difference %.2e "
              "(relative), frequency %.2e\n",
              H, peak, hz, targetSeconds, H + kAbove, band.fromHz, band.toHz, independent.curve.branch.points.size(),
              abovePeak, aboveHz, aboveSeconds, abovePeak / peak - 1, aboveHz / hz - 1);
  EXPECT_NEAR(abovePeak / peak, 1.0, kTolerance);
  EXPECT_NEAR(aboveHz / hz, 1.0, 1e-3);
}
