// Verification (issue 47, items 4 and 6): the band swept in the time domain
// (disc::sweepInTime: the ring of reduced sectors integrated at a row of frequencies,
// each from the last one's end, the first from rest), against the harmonic balance of the
// same causal model converged in the harmonics, frequency by frequency.
//
// The coarse default disc (mesh size 12, 24 sectors, EO 3), the demo's contact law (per
// area, 5000 N/mm^3, 20 kN over the face: mostly closed, sliding: a response that
// settles), 20 N at mid-blade. The hybrid models' curve with H = 3 gives the band (its
// peak's frequency less 2 %, plus 0.5 %). Reference at each frequency the sweep settled
// at: the causal model's harmonic balance with H = 10 (Newton from the H = 3 curve's
// point nearest in frequency, carried up), independent of the time stepping. Each must
// agree to 1 % (the figure) where the curve is single-valued, and the sweep's
// largest amplitude must lie within the grid's resolution of the curve's peak. Printed:
// each frequency's error and run time, and the largest point again with twice the steps
// a period (the time step's refinement level).
#include <Tpetra_Core.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "cyclone/continuation/NewtonSolve.hpp"
#include "cyclone/core/Error.hpp"
#include "cyclone/core/Log.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/disc/DiscForcedResponse.hpp"
#include "cyclone/disc/DiscPeakInTime.hpp"
#include "cyclone/disc/DiscSweepInTime.hpp"
#include "cyclone/hbm/HarmonicRefinement.hpp"
#include "cyclone/hbm/PeakMagnitude.hpp"
#include "cyclone/mesh/ShroudedSectorGenerator.hpp"
#include "cyclone/response/ForcedResponseSetup.hpp"
#include "DemoDisc.hpp"

using namespace cyclone;

TEST(DiscSweepInTime, SettledFrequenciesAreTheCausalModelsConvergedHarmonicBalance) {
  log::setQuiet(true);
  std::setvbuf(stdout, nullptr, _IOLBF, 0);
  mesh::ShroudedSectorParameters p;
  p.meshSize = 12.0;
  const auto mesh = mesh::generateShroudedSector(p);
  const auto reduced =
      demo_disc::demoDiscReducedModels(mesh, p, 4, "disc_sweep_in_time_models", Tpetra::getDefaultComm());
  const auto spec = demo_disc::demoSceneResponse(3);
  disc::DiscSweepOptions curveOptions;
  curveOptions.stability = response::ForcedResponseSetup::Stability::Never;
  curveOptions.harmonicsCheckTo = -1;
  const auto solved = disc::solveDiscForcedResponse(mesh, reduced, spec, curveOptions);
  ASSERT_FALSE(solved.curve.branch.points.empty()) << solved.curve.branch.stopReason;
  const double peakHz = solved.curve.peakOmega / (2 * M_PI);

  disc::SweepInTimeOptions options;
  options.fromHz = 0.995 * peakHz, options.toHz = 1.005 * peakHz, options.frequencies = 3, options.periods = 400;
  const auto sweep = disc::sweepInTime(solved.setup, p.sectors, spec.engineOrder, options);
  std::printf("  %s (%d steps a period, %.1f s)\n", sweep.text().c_str(), sweep.stepsPerPeriod, sweep.seconds);

  // The causal model's harmonic balance with H = 10 at each frequency.
  disc::DiscResponseSpec fine = spec;
  fine.harmonics.clear();
  for (int h = 0; h <= 10; ++h) fine.harmonics.push_back(h);
  auto fineSetup = disc::makeDiscForcedResponse(mesh, reduced, fine);
  const auto system = disc::causalTimeSystem(fineSetup, p.sectors, spec.engineOrder, options.residualHz, "test");
  const auto& traced = *solved.setup.system;
  const int out = fineSetup.outputDofs.at(0), nc = system->numCoefficients();
  const auto& curve = solved.curve;
  double worst = 0;
  int compared = 0;
  for (const auto& point : sweep.points) {
    const double omega = 2 * M_PI * point.hz;
    // Single-valued here: the traced curve passes this frequency once.
    int crossings = 0;
    std::size_t near = 0;
    for (std::size_t i = 0; i < curve.omega.size(); ++i) {
      if (i > 0 && (curve.omega[i - 1] - omega) * (curve.omega[i] - omega) <= 0) ++crossings;
      if (std::abs(curve.omega[i] - omega) < std::abs(curve.omega[near] - omega)) near = i;
    }
    Timer refTimer;
    Eigen::VectorXd X = hbm::transferCoefficients(curve.branch.points[near].x, traced.numDofs(),
                                                  traced.aft().harmonics(), system->aft().harmonics());
    const auto problem =
        response::continuationProblem(*system, response::ForcedResponseSetup::Parameter::ForceScale, omega);
    const auto newton = continuation::solveNewton(problem, X, 1.0, 1e-10);
    const double reference =
        newton.converged ? hbm::peakMagnitude(system->aft().harmonics(), Eigen::VectorXd(X.segment(out * nc, nc))) : 0;
    const double error = reference > 0 ? point.largest / reference - 1 : NAN;
    std::printf("  %.3f Hz: time domain %.6f mm (%s, %d periods, %.1f s); H = 10 %.6f mm (%.1f s): %+.2e%s\n",
                point.hz, point.largest, point.steady() ? "steady" : "not steady", point.periods, point.seconds,
                reference, refTimer.seconds(), error, crossings == 1 ? "" : " (the curve is not single-valued here)");
    EXPECT_TRUE(point.steady()) << point.hz << " Hz";
    if (crossings == 1 && newton.converged && point.steady()) {
      worst = std::max(worst, std::abs(error));
      ++compared;
    }
  }
  EXPECT_GE(compared, 2);
  EXPECT_LT(worst, 1e-2);
  // The largest amplitude lies where the curve's peak is, to the grid's step.
  EXPECT_LE(std::abs(sweep.points[sweep.largestIndex()].hz - peakHz), sweep.resolutionHz());

  // The time step's refinement level: the first frequency again (from rest) with twice
  // the steps. Its change is the central difference's error, which must leave the 1 %
  // comparison above to the harmonics: a quarter of it at most.
  disc::SweepInTimeOptions twice = options;
  twice.toHz = options.fromHz, twice.frequencies = 1, twice.periods = sweep.points[0].periods;
  twice.stepsPerPeriod = 2 * sweep.stepsPerPeriod;
  const auto refined = disc::sweepInTime(solved.setup, p.sectors, spec.engineOrder, twice);
  const double stepChange = refined.points[0].largest / sweep.points[0].largest - 1;
  std::printf("  at %.3f Hz with %d steps a period: %.6f mm (%+.2e against %d steps; %.1f s)\n", options.fromHz,
              refined.stepsPerPeriod, refined.points[0].largest, stepChange, sweep.stepsPerPeriod, refined.seconds);
  EXPECT_LT(std::abs(stepChange), 0.25e-2);
}

// The preload study's optimum is the preload whose largest amplitude is the smallest,
// marked inside the range only with a larger neighbour on each side; options out of
// range are refused naming the key.
TEST(DiscSweepInTime, TheOptimumPreloadIsMarkedInsideOnlyBetweenLargerNeighbours) {
  auto sweepWith = [](double preload, double largest) {
    disc::SweepInTime s;
    s.preload = preload;
    s.points = {{1500.0, hbm::TravellingWaveResponse::Ending::Periodic, 100, 0.5 * largest, 0.5 * largest, 1.0},
                {1510.0, hbm::TravellingWaveResponse::Ending::NotSteady, 300, largest, 0.4 * largest, 1.0},
                {1520.0, hbm::TravellingWaveResponse::Ending::Periodic, 100, 0.3 * largest, 0.3 * largest, 1.0}};
    return s;
  };
  const auto s = sweepWith(1000.0, 0.07);
  EXPECT_EQ(s.largestIndex(), 1u);
  EXPECT_DOUBLE_EQ(s.largest(), 0.07);
  EXPECT_DOUBLE_EQ(s.resolutionHz(), 10.0);
  EXPECT_FALSE(s.largestAtBandEnd());

  disc::SweepInTimeOptions bad;
  bad.fromHz = 1500, bad.toHz = 1400;
  response::ForcedResponseSetup none;
  try {
    disc::sweepInTime(none, 24, 3, bad);
    ADD_FAILURE() << "a band with from > to was swept";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("time_domain_sweep/band"), std::string::npos) << e.what();
  }
}
