// The friction-damped disc in the time domain: the default disc's ring integrated in
// time to its periodic steady state (hbm::integrateTravellingWave: the 8 sectors engine
// order 3 tells apart on 24, each with its own 43 shroud contacts, the 3D contact law
// one step at a time, every harmonic the contacts make), against the harmonic balance of
// the same reduced disc. Both take the causal modal model of the hybrid models
// (hbm::causalModalModel: their 20 modes per nodal diameter, the static correction
// realized by modes at 50 kHz, the loss factor as modal viscous damping): the same
// equations, one solved in time, the other truncated at H.
//
// The demo's contact law (per area, 5000 N/mm^3, 20 kN over the face: mostly closed,
// sliding), 20 N at mid-blade. The harmonic balance's peak over a band below the stuck
// resonance with H = 5 and H = 10; the time integration from the H = 10 peak's state at
// its frequency (1024 steps a period, checked with 2048: error against run time) and
// either side of it, the largest amplitude max |x(t)| against both peaks. H = 10 must
// be within 1 %, and nearer than H = 5: the harmonic balance converges to the time
// domain's answer. (Measured: the peaks with H = 5 2.6 % above it, H = 10 0.7 %.) About
// 6 min.
//
// Environment (for studies; the test's values otherwise): CYCLONE_TD_PRELOAD (N over the
// shroud face), CYCLONE_TD_HARMONICS (the high H), CYCLONE_TD_LOW_HARMONICS (the low H),
// CYCLONE_TD_STEPS (steps a period), CYCLONE_TD_MESH (mesh size), CYCLONE_TD_RESIDUAL_HZ,
// CYCLONE_TD_BAND (the band's lower end over the stuck resonance), CYCLONE_TD_VERBOSE.
#include <Tpetra_Core.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "cyclone/core/Log.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/disc/DiscForcedResponse.hpp"
#include "cyclone/disc/DiscHarmonicBalance.hpp"
#include "cyclone/hbm/HarmonicRefinement.hpp"
#include "cyclone/hbm/ModalReceptance.hpp"
#include "cyclone/hbm/PeakMagnitude.hpp"
#include "cyclone/hbm/TravellingWaveIntegration.hpp"
#include "cyclone/mesh/ShroudedSectorGenerator.hpp"
#include "cyclone/response/ForcedResponse.hpp"
#include "DemoDisc.hpp"

using namespace cyclone;

namespace {
double envNumber(const char* name, double fallback) {
  const char* v = std::getenv(name);
  return v && *v ? std::atof(v) : fallback;
}
// The mean and harmonic 1's cosine and sine of a period's samples.
Eigen::Vector3d firstHarmonics(const Eigen::VectorXd& x) {
  const int S = int(x.size());
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (int k = 0; k < S; ++k) {
    const double a = 2 * M_PI * k / S;
    c(0) += x(k) / S, c(1) += 2 * x(k) * std::cos(a) / S, c(2) += 2 * x(k) * std::sin(a) / S;
  }
  return c;
}
}  // namespace

namespace {
struct Curve {
  response::ForcedResponseResult result;
  std::unique_ptr<hbm::HarmonicBalanceSystem> system;
  double seconds = 0;
};

// The harmonic balance with harmonics 0..H on the causal model over [fromHz, toHz].
Curve traceBand(const mesh::Mesh& mesh, const disc::DiscReducedModels& reduced, disc::DiscResponseSpec spec, int H,
                const std::shared_ptr<hbm::ModalReceptance>& causal, double fromHz, double toHz) {
  Timer timer;
  spec.harmonics.clear();
  for (int h = 0; h <= H; ++h) spec.harmonics.push_back(h);
  response::ForcedResponseSetup setup = disc::makeDiscForcedResponse(mesh, reduced, spec);
  setup.system = hbm::withReceptance(*setup.system, causal);
  setup.system->useDynamicStiffness(true);  // the realized static correction makes A invertible
  setup.omegaUnit = 2 * M_PI * fromHz;
  setup.stability = response::ForcedResponseSetup::Stability::Never;
  setup.harmonicsCheckTo = -1;
  setup.continuation = disc::discContinuationOptions();
  setup.continuation.from = 1.0, setup.continuation.to = toHz / fromHz;
  Curve c;
  c.result = response::solveForcedResponse(setup);
  c.system = std::move(setup.system);
  c.seconds = timer.seconds();
  return c;
}

}  // namespace

TEST(DiscTimeDomain, HarmonicBalanceConvergesToTheSteadyStateInTime) {
  log::setQuiet(std::getenv("CYCLONE_TD_VERBOSE") == nullptr);
  std::setvbuf(stdout, nullptr, _IOLBF, 0);  // each line as it comes: the run is long
  mesh::ShroudedSectorParameters p;
  p.meshSize = envNumber("CYCLONE_TD_MESH", 6.0);
  const auto mesh = mesh::generateShroudedSector(p);
  const int highH = int(envNumber("CYCLONE_TD_HARMONICS", 10)), lowH = int(envNumber("CYCLONE_TD_LOW_HARMONICS", 5));
  const double preload = envNumber("CYCLONE_TD_PRELOAD", 20000.0);
  const int steps = int(envNumber("CYCLONE_TD_STEPS", 1024));

  // Every nodal diameter engine order 3 reaches on 24 sectors (0, 3, .., 12): the time
  // integration keeps all harmonics the contacts make.
  std::vector<int> all;
  for (int h = 0; h <= 8; ++h) all.push_back(h);
  const auto reduced = disc::buildDiscReducedModels(mesh, demo_disc::demoDiscModels(p),
                                                    disc::nodalDiametersFor(p.sectors, 3, all), "disc_time_domain_models",
                                                    Tpetra::getDefaultComm());
  disc::DiscResponseSpec spec = demo_disc::demoDiscResponse(1);
  spec.contact.law = disc::ShroudContactSpec::Law::PerArea;  // the demo's law
  spec.contact.kn = spec.contact.kt = 5000.0;
  spec.contact.preload = preload;

  response::ForcedResponseSetup setup = disc::makeDiscForcedResponse(mesh, reduced, spec);
  std::vector<long> phases;
  for (long q = 0; q < p.sectors; q += 3) phases.push_back(q);
  const double residualHz = envNumber("CYCLONE_TD_RESIDUAL_HZ", 50000.0);
  const auto causal = hbm::causalModalModel(*setup.system->receptance(), phases, 2 * M_PI * residualHz);
  setup.system = hbm::withReceptance(*setup.system, causal);
  setup.system->useDynamicStiffness(true);
  const auto estimate = disc::estimateResonance(setup, reduced);
  const double fromHz = envNumber("CYCLONE_TD_BAND", 0.98) * estimate.stuckHz, toHz = estimate.stuckHz;
  const int out = setup.outputDofs.at(0);

  // The harmonic balance with a low and a high H over the band.
  const Curve low = traceBand(mesh, reduced, spec, lowH, causal, fromHz, toHz);
  const Curve high = traceBand(mesh, reduced, spec, highH, causal, fromHz, toHz);
  for (const Curve* c : {&low, &high}) {
    ASSERT_FALSE(c->result.branch.points.empty()) << c->result.branch.stopReason;
    std::printf("preload %.0f N, H = %d: harmonic balance over %.1f..%.1f Hz, %zu points, %.1f s; peak %.6f mm at "
                "%.3f Hz (%s)\n",
                preload, c->system->aft().harmonics().maxHarmonic(), fromHz, toHz, c->result.branch.points.size(),
                c->seconds, c->result.peak, c->result.peakOmega / (2 * M_PI),
                c->result.branch.finished ? "finished" : c->result.branch.stopReason.c_str());
  }

  // The time integration at the high H's peak, from its state.
  const auto& peak = high.result.branch.points[high.result.peakIndex];
  const double w = high.result.peakOmega;
  hbm::TravellingWaveOptions opt;
  opt.stepsPerPeriod = steps;
  opt.steadyDofs = {out};
  opt.amplitudeTolerance = 1e-3;  // the comparison is at 1 %; the stick-slip chatter of an explicit step moves it 1e-4
  const hbm::TravellingWaveState start = hbm::travellingWaveStart(*high.system, peak.x, w);
  const auto td = hbm::integrateTravellingWave(*high.system, w, opt, &start);
  hbm::TravellingWaveOptions fine = opt;
  fine.stepsPerPeriod = 2 * td.stepsPerPeriod;
  const auto tdFine = hbm::integrateTravellingWave(*high.system, w, fine, &td.state);
  auto ending = [](const hbm::TravellingWaveResponse& r) {
    char text[96];
    if (r.ending == hbm::TravellingWaveResponse::Ending::Periodic)
      std::snprintf(text, sizeof text, "periodic to %.0e", r.errorEstimate);
    else
      std::snprintf(text, sizeof text, "amplitude steady to %.0e, still changing %.0e a period", r.amplitudeSpread,
                    r.periodChange);
    return std::string(text);
  };
  const double a = td.peak(out), aFine = tdFine.peak(out);
  std::printf("time domain at %.3f Hz: %.6f mm (%d steps a period, %d periods, %s; %d sectors, %d modes, %.1f s); "
              "with %d steps %.6f mm (%d periods, %.1f s): the steps change it by %.1e\n",
              w / (2 * M_PI), a, td.stepsPerPeriod, td.periods, ending(td).c_str(), td.sectors, td.modes, td.seconds,
              tdFine.stepsPerPeriod, aFine, tdFine.periods, tdFine.seconds, aFine / a - 1);
  // The mean and the first harmonic apart (a contact stuck all period keeps its stuck
  // position where the history left it: the mean is not the harmonic balance's to compare).
  const int nc = high.system->numCoefficients();
  const Eigen::Vector3d td01 = firstHarmonics(tdFine.motion.col(out));
  std::printf("  mean %.6f mm (time domain %.6f), first harmonic %.6f mm (time domain %.6f)\n", peak.x(out * nc),
              td01(0), std::hypot(peak.x(out * nc + 1), peak.x(out * nc + 2)), std::hypot(td01(1), td01(2)));
  // Either side of it (0.05 %, about the H = 10 curve's top), from its end: the time
  // domain's peak is the largest of the three. The top is a fold: below it the motion
  // leaves for the lower branch (measured: 0.13 mm after 682 periods), a side that does
  // not settle within 300 periods is left out.
  double tdPeak = aFine;
  hbm::TravellingWaveOptions side = opt;
  side.maxPeriods = 300;
  for (double f : {1 - 5e-4, 1 + 5e-4}) {
    const auto r = hbm::integrateTravellingWave(*high.system, f * w, side, &td.state);
    std::printf("time domain at %.3f Hz: %.6f mm (%d periods, %.1f s)%s\n", f * w / (2 * M_PI), r.peak(out),
                r.periods, r.seconds, r.converged ? "" : ", not steady: left out");
    if (r.converged) tdPeak = std::max(tdPeak, r.peak(out));
  }
  const double highError = std::abs(high.result.peak / tdPeak - 1), lowError = std::abs(low.result.peak / tdPeak - 1);
  std::printf("peaks against the time domain's %.6f mm: H = %d %.6f mm (%.2e), H = %d %.6f mm (%.2e)\n", tdPeak, lowH,
              low.result.peak, lowError, highH, high.result.peak, highError);
  EXPECT_TRUE(td.converged && tdFine.converged);
  EXPECT_LT(std::abs(aFine / a - 1), 2e-3);
  EXPECT_LT(highError, 0.01);
  EXPECT_LT(highError, lowError);
}
