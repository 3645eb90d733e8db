// Study program (not a test): the default disc's friction-damped response in the time
// domain over a band of frequencies, the reference where the harmonic balance cannot
// carry the harmonics (the shroud hammering). The causal modal model of the demo's
// hybrid models (hbm::causalModalModel: 20 modes per nodal diameter, the static
// correction realized by modes at 50 kHz, the loss factor as viscous damping), the demo's
// contact law per area at the given preload, 20 N at mid-blade. Each frequency from the
// previous one's end (the first from rest), in the given order; per frequency the
// amplitude max |x(t)| of the mid-blade DOF, how the run ended, periods and time. Then
// the harmonic balance's peaks on the same model with H = 1, 2, ... up to the given H
// over the same band (each traced whole; a trace that stops says where).
//   build/regression/disc_time_domain_sweep [preload N (2000)] [from Hz (1400)] [to Hz (1560)]
//                                          [frequencies (9)] [steps a period (1024)] [H (3)]
//                                          [max periods (1500)] [history csv ("")]
//                                          [Hill's method at these Hz ("": none), e.g. 1500,1520]
// The csv (if named): frequency, period, max |x(t)| over that period, for every
// frequency: how each run settled, or what the motion did where it did not. With
// frequencies for Hill's method, each harmonic balance curve's point nearest each is
// checked (its leading Floquet exponent): whether the periodic solution the ring does
// not settle on is unstable there. 0 frequencies skip the time domain.
#include <cmath>
#include <cstdio>
#include <complex>
#include <cstdlib>
#include <string>

#include "cyclone/core/Timer.hpp"
#include "cyclone/disc/DiscForcedResponse.hpp"
#include "cyclone/disc/DiscHarmonicBalance.hpp"
#include "cyclone/fe/Environment.hpp"
#include "cyclone/hbm/HarmonicRefinement.hpp"
#include "cyclone/hbm/HillStability.hpp"
#include "cyclone/hbm/ModalReceptance.hpp"
#include "cyclone/hbm/TravellingWaveIntegration.hpp"
#include "cyclone/mesh/ShroudedSectorGenerator.hpp"
#include "cyclone/response/ForcedResponse.hpp"
#include "DemoDisc.hpp"

using namespace cyclone;

int main(int argc, char** argv) {
  Environment env(argc, argv);
  const double preload = argc > 1 ? std::atof(argv[1]) : 2000.0;
  const double fromHz = argc > 2 ? std::atof(argv[2]) : 1400.0;
  const double toHz = argc > 3 ? std::atof(argv[3]) : 1560.0;
  const int count = argc > 4 ? std::atoi(argv[4]) : 9;
  const int steps = argc > 5 ? std::atoi(argv[5]) : 1024;
  const int maxH = argc > 6 ? std::atoi(argv[6]) : 3;
  const int maxPeriods = argc > 7 ? std::atoi(argv[7]) : 1500;
  const std::string historyFile = argc > 8 ? argv[8] : "";
  std::vector<double> hillHz;
  for (std::string rest = argc > 9 ? argv[9] : ""; !rest.empty();) {
    const auto comma = rest.find(',');
    hillHz.push_back(std::atof(rest.substr(0, comma).c_str()));
    rest = comma == std::string::npos ? "" : rest.substr(comma + 1);
  }
  std::setvbuf(stdout, nullptr, _IOLBF, 0);

  mesh::ShroudedSectorParameters p;
  const auto mesh = mesh::generateShroudedSector(p);
  std::vector<int> all;
  for (int h = 0; h <= 8; ++h) all.push_back(h);
  const auto reduced = disc::buildDiscReducedModels(mesh, demo_disc::demoDiscModels(p),
                                                    disc::nodalDiametersFor(p.sectors, 3, all),
                                                    "disc_time_domain_models", env.comm());
  disc::DiscResponseSpec spec = demo_disc::demoDiscResponse(1);
  spec.contact.law = disc::ShroudContactSpec::Law::PerArea;
  spec.contact.kn = spec.contact.kt = 5000.0;
  spec.contact.preload = preload;
  std::vector<long> phases;
  for (long q = 0; q < p.sectors; q += 3) phases.push_back(q);
  auto base = disc::makeDiscForcedResponse(mesh, reduced, spec);
  const auto causal = hbm::causalModalModel(*base.system->receptance(), phases, 2 * M_PI * 50000.0);
  const auto system = hbm::withReceptance(*base.system, causal);
  const int out = base.outputDofs.at(0);

  std::printf("preload %.0f N over the shroud face, 20 N at mid-blade; time domain, %d steps a period:\n", preload,
              steps);
  hbm::TravellingWaveOptions opt;
  opt.stepsPerPeriod = steps, opt.maxPeriods = maxPeriods;
  opt.steadyDofs = {out};
  opt.amplitudeTolerance = 1e-3;
  hbm::TravellingWaveState state;
  double best = 0, bestHz = 0;
  std::FILE* history = historyFile.empty() ? nullptr : std::fopen(historyFile.c_str(), "w");
  if (history) std::fprintf(history, "frequency_hz,period,amplitude_mm\n");
  Timer total;
  for (int i = 0; i < count; ++i) {  // count 0: no time domain
    const double hz = count == 1 ? fromHz : fromHz + (toHz - fromHz) * i / (count - 1);
    const auto r = hbm::integrateTravellingWave(*system, 2 * M_PI * hz, opt, i == 0 ? nullptr : &state);
    state = r.state;
    const char* how = r.ending == hbm::TravellingWaveResponse::Ending::Periodic          ? "periodic"
                      : r.ending == hbm::TravellingWaveResponse::Ending::SteadyAmplitude ? "amplitude steady"
                                                                                          : "not steady";
    std::printf("  %9.3f Hz  %.6f mm  (%s; %d periods of %d steps, %d modes, change %.1e a period, amplitude spread %.1e; %.1f s)\n", hz,
                r.peak(out), how, r.periods, r.stepsPerPeriod, r.modes, r.periodChange, r.amplitudeSpread, r.seconds);
    if (r.converged && r.peak(out) > best) best = r.peak(out), bestHz = hz;
    if (history)
      for (std::size_t k = 0; k < r.amplitudeHistory.size(); ++k)
        std::fprintf(history, "%.3f,%zu,%.9g\n", hz, k + 1, r.amplitudeHistory[k]);
  }
  if (history) std::fclose(history);
  if (best > 0)
    std::printf("time domain: largest steady amplitude %.6f mm at %.3f Hz (%.0f s in all)\n", best, bestHz,
                total.seconds());
  else
    std::printf("time domain: no frequency steady (%.0f s in all)\n", total.seconds());

  for (int H = 1; H <= maxH; ++H) {
    Timer timer;
    disc::DiscResponseSpec s = spec;
    s.harmonics.clear();
    for (int h = 0; h <= H; ++h) s.harmonics.push_back(h);
    auto setup = disc::makeDiscForcedResponse(mesh, reduced, s);
    setup.system = hbm::withReceptance(*setup.system, causal);
    setup.system->useDynamicStiffness(true);
    setup.omegaUnit = 2 * M_PI * fromHz;
    setup.stability = response::ForcedResponseSetup::Stability::Never;
    setup.harmonicsCheckTo = -1;
    setup.continuation = disc::discContinuationOptions();
    setup.continuation.from = 1.0, setup.continuation.to = toHz / fromHz;
    setup.continuation.maxSteps = 1500;
    const auto curve = response::solveForcedResponse(setup);
    std::printf("harmonic balance H = %d: peak %.6f mm at %.3f Hz (%zu points, %.1f s; %s)\n", H, curve.peak,
                curve.peakOmega / (2 * M_PI), curve.branch.points.size(), timer.seconds(),
                curve.branch.finished ? "finished" : curve.branch.stopReason.c_str());
    for (double hz : hillHz) {
      std::size_t near = 0;
      for (std::size_t i = 0; i < curve.omega.size(); ++i)
        if (std::abs(curve.omega[i] / (2 * M_PI) - hz) < std::abs(curve.omega[near] / (2 * M_PI) - hz)) near = i;
      if (curve.omega.empty()) break;
      Timer hill;
      const auto fl = hbm::hillStability(*setup.system, curve.branch.points[near].x, curve.omega[near]);
      const std::complex<double> lead = fl.exponents.size() ? fl.exponents(0) : std::complex<double>(0, 0);
      std::printf("  Hill at %.3f Hz (%.6f mm): %s, leading exponent %.3g %+.3gi /s (%.1f s)\n",
                  curve.omega[near] / (2 * M_PI), curve.measure[near], fl.stable ? "stable" : "unstable", lead.real(),
                  lead.imag(), hill.seconds());
    }
  }
  return 0;
}
