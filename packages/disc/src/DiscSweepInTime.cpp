#include "cyclone/disc/DiscSweepInTime.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <tuple>

#include "cyclone/core/Error.hpp"
#include "cyclone/core/Log.hpp"
#include "cyclone/core/NumberText.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/disc/DiscPeakInTime.hpp"
#include "cyclone/hbm/HarmonicRefinement.hpp"
#include "cyclone/response/ForcedResponseSetup.hpp"

namespace cyclone::disc {

namespace {

constexpr const char* kKey = "disc_response/time_domain_sweep";

// The options with the band required (the scene's default band is set after the curve).
void checkOptions(const SweepInTimeOptions& o) {
  if (o.fromHz == 0 && o.toHz == 0) throw InputError(std::string(kKey) + "/band", "needs [from, to] in Hz");
  try {
    checkSweepInTimeOptions(o);
  } catch (const InputError& e) {
    throw InputError(std::string(kKey) + "/" + e.where(), e.problem());
  }
}

}  // namespace

void checkSweepInTimeOptions(const SweepInTimeOptions& o) {
  if (o.frequencies < 1 || o.frequencies > 1000) throw InputError("frequencies", "must lie in 1..1000");
  const bool band = !(o.fromHz == 0 && o.toHz == 0);  // 0, 0: the caller's default, set later
  if (band && !(o.fromHz > 0 && std::isfinite(o.toHz) && (o.toHz > o.fromHz || (o.frequencies == 1 && o.toHz == o.fromHz))))
    throw InputError("band", "needs [from, to] in Hz with 0 < from < to");
  if (o.periods < 100) throw InputError("periods", "must be at least 100 (the steadiness is judged over the last 50)");
  // The time-domain check's limits, per frequency (the first frequency's run, from rest,
  // takes up to twice the periods).
  if (o.stepsPerPeriod < 16 || o.stepsPerPeriod > kPeakInTimeMaxStepsPerPeriod)
    throw InputError("steps_per_period", "must lie in 16.." + std::to_string(kPeakInTimeMaxStepsPerPeriod));
  if (2.0 * double(o.periods) * double(o.stepsPerPeriod) > double(kPeakInTimeMaxSteps))
    throw InputError("periods", "twice the periods times steps_per_period (the first frequency's run) must be at "
                                "most " + numberText(double(kPeakInTimeMaxSteps)));
  if (!(o.residualHz > 0) || !(o.amplitudeTolerance > 0))
    throw InputError("residual frequency", "the residual frequency and the amplitude tolerance must be positive");
}

std::size_t SweepInTime::largestIndex() const {
  std::size_t best = 0;
  for (std::size_t i = 1; i < points.size(); ++i)
    if (points[i].largest > points[best].largest) best = i;
  return best;
}

double SweepInTime::resolutionHz() const {
  return points.size() < 2 ? 0 : (points.back().hz - points.front().hz) / double(points.size() - 1);
}

bool SweepInTime::largestAtBandEnd() const {
  const std::size_t i = largestIndex();
  return !points.empty() && (i == 0 || i + 1 == points.size());
}

std::string SweepInTime::text() const {
  std::ostringstream line;
  if (points.empty()) return "no frequency swept";
  const auto& p = points[largestIndex()];
  line << "largest max|x(t)| " << numberText(p.largest) << " at " << numberText(p.hz) << " Hz (";
  if (p.steady())
    line << "steady";
  else
    line << "not steady in " << p.periods << " periods: between " << numberText(p.smallest) << " and "
         << numberText(p.largest) << " per period";
  line << "; the grid's step " << numberText(resolutionHz(), 3) << " Hz";
  if (largestAtBandEnd()) line << "; at the band's end: the resonance may lie outside it";
  line << ")";
  return line.str();
}

SweepInTime sweepInTime(const response::ForcedResponseSetup& setup, long sectors, int engineOrder,
                        const SweepInTimeOptions& options, const std::function<void(const SweepInTimePoint&)>& progress) {
  checkOptions(options);
  if (setup.outputDofs.empty()) throw InputError(kKey, "needs an output DOF");
  Timer timer;
  const auto system = causalTimeSystem(setup, sectors, engineOrder, options.residualHz, kKey);
  const int out = setup.outputDofs.front();
  auto opt = travellingWaveOptions(setup, options.stepsPerPeriod, options.periods, options.amplitudeTolerance);
  SweepInTime sweep;
  hbm::TravellingWaveState state;
  for (int i = 0; i < options.frequencies; ++i) {
    const double hz =
        options.frequencies == 1 ? options.fromHz : options.fromHz + (options.toHz - options.fromHz) * i / (options.frequencies - 1);
    // Each frequency from the last one's end: the sweep stays on the branch it is on
    // until that branch ends (a fold), as a test rig's stepped sine does.
    // The first from rest: its transient is the free vibration's, which the light
    // damping keeps for hundreds of periods (about 370 to fall to 1e-3 with a loss
    // factor of 0.006), so it gets twice the periods; the others start next to their
    // steady state.
    opt.maxPeriods = i == 0 ? 2 * options.periods : options.periods;
    const auto r = hbm::integrateTravellingWave(*system, 2 * M_PI * hz, opt, i == 0 ? nullptr : &state);
    state = r.state;
    SweepInTimePoint p;
    p.hz = hz;
    p.ending = r.ending;
    p.periods = r.periods;
    p.seconds = r.seconds;
    if (p.steady()) p.largest = p.smallest = r.peak(out);
    else std::tie(p.largest, p.smallest) = modulationRange(r.amplitudeHistory);
    sweep.stepsPerPeriod = r.stepsPerPeriod, sweep.sectors = r.sectors;
    sweep.points.push_back(p);
    if (progress) progress(p);
  }
  sweep.seconds = timer.seconds();
  return sweep;
}

std::string PreloadSweepsInTime::text() const {
  std::ostringstream line;
  line << "the ring in time swept over " << (sweeps.empty() || sweeps[0].points.empty() ? std::string("no band")
                                                  : numberText(sweeps[0].points.front().hz) + ".." +
                                                        numberText(sweeps[0].points.back().hz) + " Hz")
       << " at " << sweeps.size() << " preloads (" << std::lround(seconds) << " s): largest max|x(t)|";
  for (std::size_t i = 0; i < sweeps.size(); ++i) {
    const auto& s = sweeps[i];
    const auto& p = s.points[s.largestIndex()];
    line << (i ? ", " : " ") << numberText(s.largest()) << " at " << numberText(s.preload) << " N";
    if (!p.steady()) line << " (not steady)";
  }
  if (optimum >= 0) {
    const auto& best = sweeps[std::size_t(optimum)];
    line << "; smallest " << numberText(best.largest()) << " at preload " << numberText(best.preload) << " N ("
         << (optimumInside() ? "inside the range: the optimum preload lies between its neighbours, "
                             : "at the range's end: the optimum may lie beyond it, ")
         << numberText(sweeps[std::size_t(optimum)].points[best.largestIndex()].hz) << " Hz)";
  }
  return line.str();
}

PreloadSweepsInTime sweepPreloadsInTime(const mesh::Mesh& mesh, const DiscReducedModels& models,
                                        const DiscResponseSpec& spec, const std::vector<double>& preloads,
                                        const SweepInTimeOptions& options,
                                        const std::function<void(const SweepInTimePoint&)>& progress) {
  checkOptions(options);
  if (preloads.empty()) throw InputError(std::string(kKey) + "/preloads", "needs at least one preload");
  for (std::size_t i = 0; i < preloads.size(); ++i)
    if (!(preloads[i] >= 0 && std::isfinite(preloads[i])) || (i > 0 && !(preloads[i] > preloads[i - 1])))
      throw InputError(std::string(kKey) + "/preloads", "must be >= 0 and increasing");
  Timer timer;
  PreloadSweepsInTime out;
  for (double preload : preloads) {
    DiscResponseSpec at = spec;
    at.contact.preload = preload;
    const auto setup = makeDiscForcedResponse(mesh, models, at, 0.5 * (options.fromHz + options.toHz));
    log::info("time domain: the band swept at preload " + numberText(preload) + " N");
    auto sweep = sweepInTime(setup, models.sectors, spec.engineOrder, options, progress);
    sweep.preload = preload;
    out.sweeps.push_back(std::move(sweep));
  }
  for (std::size_t i = 0; i < out.sweeps.size(); ++i)
    if (out.optimum < 0 || out.sweeps[i].largest() < out.sweeps[std::size_t(out.optimum)].largest()) out.optimum = int(i);
  out.seconds = timer.seconds();
  return out;
}

}  // namespace cyclone::disc
