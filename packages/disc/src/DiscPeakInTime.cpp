#include "cyclone/disc/DiscPeakInTime.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>
#include <tuple>

#include "cyclone/core/Error.hpp"
#include "cyclone/core/Log.hpp"
#include "cyclone/core/NumberText.hpp"
#include "cyclone/hbm/HarmonicRefinement.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/hbm/ModalReceptance.hpp"
#include "cyclone/hbm/PeakMagnitude.hpp"
#include "cyclone/response/ForcedResponseSetup.hpp"

namespace cyclone::disc {

namespace {

std::string peakInTimeText(const PeakInTime& r) {
  std::ostringstream line;
  line << "time-domain check at " << numberText(r.hz) << " Hz (the ring of " << r.sectors
       << " sectors integrated from the harmonic balance's state, " << r.stepsPerPeriod << " steps a period, "
       << r.periods << " periods, " << std::lround(r.seconds) << " s): ";
  if (r.steady()) {
    line << "steady, max|x(t)| " << numberText(r.largest) << " against the harmonic balance's "
         << numberText(r.harmonicBalance) << " (" << (r.difference() >= 0 ? "+" : "")
         << numberText(100 * r.difference(), 3) << " %";
    if (r.agrees())
      line << "; the time domain's causal model alone differs by a few percent: its static correction is realized "
              "by modes)";
    else
      line << ", more than the two models differ: started from the harmonic balance's periodic state the disc "
              "settles on another motion, so the harmonic balance's peak is not the disc's amplitude there, and the "
              "disc's own peak may lie elsewhere in the band)";
  } else {
    line << "not steady: max|x(t)| per period between " << numberText(r.smallest) << " and " << numberText(r.largest)
         << " over the last quarter of the run, against the harmonic balance's periodic " << numberText(r.harmonicBalance)
         << ": the disc does not settle on that periodic response; its amplitude at this frequency is the "
            "modulated motion's, and the disc's own peak may lie elsewhere in the band (where the periodic "
            "response is not the disc's, only a sweep in time finds it)";
  }
  return line.str();
}

}  // namespace

std::unique_ptr<hbm::HarmonicBalanceSystem> causalTimeSystem(const response::ForcedResponseSetup& setup, long sectors,
                                                             int engineOrder, double residualHz, const std::string& key) {
  if (!setup.system->receptance())
    throw InputError(key, "needs reduced models with modes (hybrid, truncation, Guyan or Craig-Bampton): the time "
                          "domain integrates their modes");
  const long step = std::gcd(long(engineOrder), sectors);
  std::vector<long> phases;
  for (long q = 0; q < sectors; q += step) phases.push_back(q);
  const auto causal = hbm::causalModalModel(*setup.system->receptance(), phases, 2 * M_PI * residualHz);
  auto timeSystem = hbm::withReceptance(*setup.system, causal);
  timeSystem->useDynamicStiffness(true);  // the realized static correction makes its dynamic stiffness invertible
  return timeSystem;
}

hbm::TravellingWaveOptions travellingWaveOptions(const response::ForcedResponseSetup& setup, int stepsPerPeriod,
                                                 int maxPeriods, double amplitudeTolerance) {
  hbm::TravellingWaveOptions opt;
  opt.stepsPerPeriod = stepsPerPeriod;
  opt.maxPeriods = maxPeriods;
  opt.steadyDofs = {setup.outputDofs.front()};
  opt.amplitudeTolerance = amplitudeTolerance;
  opt.excitationScale = setup.excitationScale;
  return opt;
}

std::pair<double, double> modulationRange(const std::vector<double>& a) {
  if (a.empty()) return {0.0, 0.0};
  // On the hammering default disc it took 200 of 400 periods to leave the periodic
  // state, and its modulation's cycle is about 45 periods (docs/studies/time_domain_disc.md).
  const auto tail = a.end() - std::min<long>(long(a.size()), std::max<long>(50, long(a.size()) / 4));
  return {*std::max_element(tail, a.end()), *std::min_element(tail, a.end())};
}

void checkPeakInTimeOptions(const PeakInTimeOptions& o) {
  if (o.maxPeriods < 2 * 50)
    throw InputError("periods", std::to_string(o.maxPeriods) + ": must be at least 100 (the steadiness is judged over "
                                                               "the last 50)");
  if (o.stepsPerPeriod < 16 || o.stepsPerPeriod > kPeakInTimeMaxStepsPerPeriod)
    throw InputError("steps_per_period", std::to_string(o.stepsPerPeriod) + ": must lie in 16.." +
                                             std::to_string(kPeakInTimeMaxStepsPerPeriod) +
                                             " (the ring's motion over a period is held in memory, twice)");
  if (const double steps = double(o.maxPeriods) * double(o.stepsPerPeriod); steps > double(kPeakInTimeMaxSteps))
    throw InputError(o.maxPeriods / 600.0 >= o.stepsPerPeriod / 1024.0 ? "periods" : "steps_per_period",
                     std::to_string(o.maxPeriods) + " periods of " + std::to_string(o.stepsPerPeriod) +
                         " steps are " + numberText(steps) + " steps, more than the " +
                         numberText(double(kPeakInTimeMaxSteps)) +
                         " the check takes (the default's 600 x 1024 is 614400, about 70 s on the default disc at mesh "
                         "size 12; each step updates every sector's modes and contacts)");
  if (!(o.residualHz > 0)) throw InputError("residual frequency", "must be positive");
}

PeakInTime integratePeakInTime(const response::ForcedResponseSetup& setup, const Eigen::VectorXd& x, double omega,
                               long sectors, int engineOrder, const PeakInTimeOptions& options) {
  const auto& system = *setup.system;
  if (setup.outputDofs.empty()) throw InputError("disc_response/time_domain_check", "needs an output DOF");
  try {
    checkPeakInTimeOptions(options);
  } catch (const InputError& e) {
    throw InputError("disc_response/time_domain_check/" + e.where(), e.problem());
  }
  Timer timer;
  const auto timeSystem = causalTimeSystem(setup, sectors, engineOrder, options.residualHz, "disc_response/time_domain_check");
  const int out = setup.outputDofs.front();
  const auto opt = travellingWaveOptions(setup, options.stepsPerPeriod, options.maxPeriods, options.amplitudeTolerance);
  const hbm::TravellingWaveState start = hbm::travellingWaveStart(*timeSystem, x, omega, setup.excitationScale);
  const auto td = hbm::integrateTravellingWave(*timeSystem, omega, opt, &start);

  PeakInTime r;
  r.hz = omega / (2 * M_PI);
  const int nc = system.numCoefficients();
  r.harmonicBalance = hbm::peakMagnitude(system.aft().harmonics(), Eigen::VectorXd(x.segment(out * nc, nc)));
  r.ending = td.ending;
  r.periods = td.periods, r.stepsPerPeriod = td.stepsPerPeriod, r.sectors = td.sectors;
  r.amplitudeHistory = td.amplitudeHistory;
  r.lastAmplitude = td.peak(out);
  if (r.steady()) r.largest = r.smallest = r.lastAmplitude;
  else std::tie(r.largest, r.smallest) = modulationRange(r.amplitudeHistory);
  r.seconds = timer.seconds();
  r.text = peakInTimeText(r);
  return r;
}

}  // namespace cyclone::disc
