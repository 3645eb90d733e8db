// Verification (issue 47, item 4): the friction-damped peak checked in the time domain
// (disc::integratePeakInTime, asked for by DiscSweepOptions::peakInTime), against the
// harmonic balance of the same causal model converged in the harmonics.
//
// The coarse default disc (mesh size 12, 24 sectors, EO 3), the demo's contact law (per
// area, 5000 N/mm^3, 20 kN over the face: mostly closed, sliding), 20 N at mid-blade.
// solveDiscForcedResponse traces the hybrid models' curve with H = 3 and integrates the
// ring in time at its largest point, from that periodic state (the causal model: the
// hybrid models' modes, the static correction realized by modes at 50 kHz). Reference:
// the same causal model's harmonic balance with H = 10 at that frequency (Newton from the
// H = 3 solution carried up), independent of the time stepping. The time domain must
// settle and agree with it to 1 % (the figure); the hybrid H = 3 peak is printed
// beside it (its difference is the two models' and the harmonics').
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
#include "cyclone/hbm/HarmonicRefinement.hpp"
#include "cyclone/hbm/ModalReceptance.hpp"
#include "cyclone/hbm/PeakMagnitude.hpp"
#include "cyclone/mesh/ShroudedSectorGenerator.hpp"
#include "cyclone/response/ForcedResponseSetup.hpp"
#include "DemoDisc.hpp"

using namespace cyclone;

TEST(DiscPeakInTime, SteadyPeakIsTheCausalModelsConvergedHarmonicBalance) {
  log::setQuiet(true);
  std::setvbuf(stdout, nullptr, _IOLBF, 0);
  mesh::ShroudedSectorParameters p;
  p.meshSize = 12.0;
  const auto mesh = mesh::generateShroudedSector(p);
  // Harmonics 0..4 reach every nodal diameter EO 3 reaches on 24 sectors (0, 3, .., 12),
  // so the reference's H = 10 needs no other model.
  const auto reduced =
      demo_disc::demoDiscReducedModels(mesh, p, 4, "disc_peak_in_time_models", Tpetra::getDefaultComm());
  const disc::DiscResponseSpec spec = demo_disc::demoSceneResponse(3);  // the demo's law and preload
  disc::DiscSweepOptions sweep;
  sweep.stability = response::ForcedResponseSetup::Stability::Never;
  sweep.peakInTime = disc::PeakInTimeOptions{};
  Timer timer;
  const auto solved = disc::solveDiscForcedResponse(mesh, reduced, spec, sweep);
  const double traceSeconds = timer.seconds();
  ASSERT_TRUE(solved.headline.found());
  ASSERT_TRUE(solved.peakInTime.has_value());
  const auto& td = *solved.peakInTime;
  std::printf("  %s\n", td.text.c_str());
  ASSERT_TRUE(td.steady()) << td.text;

  // The causal model's harmonic balance with H = 10 at the same frequency.
  Timer refTimer;
  const double omega = solved.curve.peakOmega;
  disc::DiscResponseSpec fine = spec;
  fine.harmonics.clear();
  for (int h = 0; h <= 10; ++h) fine.harmonics.push_back(h);
  auto setup = disc::makeDiscForcedResponse(mesh, reduced, fine);
  std::vector<long> phases;
  for (long q = 0; q < p.sectors; q += 3) phases.push_back(q);
  const auto causal = hbm::causalModalModel(*setup.system->receptance(), phases, 2 * M_PI * 50000.0);
  auto system = hbm::withReceptance(*setup.system, causal);
  system->useDynamicStiffness(true);
  const auto& traced = *solved.setup.system;
  Eigen::VectorXd X = hbm::transferCoefficients(solved.curve.branch.points[solved.curve.peakIndex].x,
                                                traced.numDofs(), traced.aft().harmonics(), system->aft().harmonics());
  const auto problem = response::continuationProblem(*system, response::ForcedResponseSetup::Parameter::ForceScale, omega);
  const auto newton = continuation::solveNewton(problem, X, 1.0, 1e-10);
  ASSERT_TRUE(newton.converged) << "H = 10 on the causal model at " << omega / (2 * M_PI) << " Hz";
  const int out = setup.outputDofs.at(0), nc = system->numCoefficients();
  const double reference = hbm::peakMagnitude(system->aft().harmonics(), Eigen::VectorXd(X.segment(out * nc, nc)));
  const double difference = td.largest / reference - 1;
  std::printf("  at %.4f Hz: time domain %.6f mm (%d periods, %.1f s); causal model, harmonic balance H = 10 %.6f mm "
              "(%.1f s): %+.2e; hybrid model H = 3 %.6f mm (the curve, %.1f s with the time domain)\n",
              omega / (2 * M_PI), td.largest, td.periods, td.seconds, reference, refTimer.seconds(), difference,
              td.harmonicBalance, traceSeconds);
  EXPECT_LT(std::abs(difference), 1e-2);
  EXPECT_TRUE(td.agrees()) << td.text;  // within the two models' difference of the hybrid H = 3 point
}

// What cannot be integrated is refused naming the key: a matrix system has no modes.
TEST(DiscPeakInTime, AMatrixSystemIsRefusedNamingTheKey) {
  Eigen::MatrixXd M = Eigen::MatrixXd::Identity(1, 1), C = 0.01 * M, K = M;
  response::ForcedResponseSetup setup;
  setup.system = std::make_unique<hbm::HarmonicBalanceSystem>(M, C, K, hbm::HarmonicSet::upTo(1), 16);
  setup.outputDofs = {0};
  try {
    disc::integratePeakInTime(setup, Eigen::VectorXd::Zero(3), 1.0, 24, 3);
    ADD_FAILURE() << "a matrix system was integrated";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("time_domain_check"), std::string::npos) << e.what();
  }
}
