// disc_response's keys for the curve (family, range, stability, the continuation), read
// onto the disc's sweep options.
#include <cmath>
#include <string>
#include <vector>

#include "cyclone/core/Error.hpp"
#include "cyclone/disc/DiscForcedResponse.hpp"
#include "cyclone/disc/DiscPeakInTime.hpp"
#include "cyclone/scenes/SceneSection.hpp"
#include "DiscStages.hpp"

namespace cyclone::scenes {

// disc_response's keys for the curve: family, frequency_range_hz, stability and the
// continuation section (the disc's own defaults, discContinuationOptions, then the
// scene's keys; an engine the scene names is used alone, by default the other one
// retraces a curve the first leaves incomplete).
disc::DiscSweepOptions readSweepOptions(SceneSection& d, const DiscPlan& plan,
                                        const std::shared_ptr<continuation::TraceCheckpoints>& checkpoints) {
  disc::DiscSweepOptions sweep;
  sweep.family = d.getInt("family", 1);
  // Against the models' modes before they are built (99 was refused after them; issue 49).
  if (sweep.family < 1 || sweep.family > plan.modelSpec.modes)
    throw InputError(d.where("family"), std::to_string(sweep.family) + ": must lie in 1.." +
                                            std::to_string(plan.modelSpec.modes) +
                                            " (the natural frequencies computed per nodal diameter, reduced_model/modes)");
  const auto range = d.getDoubleList("frequency_range_hz", {});
  if (!range.empty() && (range.size() != 2 || !(range[0] > 0) || !(range[1] > range[0])))
    throw InputError(d.where("frequency_range_hz"), "needs two increasing positive frequencies [from, to] in Hz");
  if (!range.empty()) sweep.fromHz = range[0], sweep.toHz = range[1];
  sweep.mustCoverHz = plan.peakStress.atHz;
  if (!range.empty() && sweep.mustCoverHz > 0 && !(sweep.mustCoverHz >= range[0] && sweep.mustCoverHz <= range[1]))
    throw InputError(d.where("peak_stress/at_hz"), std::to_string(sweep.mustCoverHz) +
                                                       " Hz lies outside disc_response/frequency_range_hz");
  // The peak checked in the time domain: asked for by the section, e.g. {periods: 600}.
  if (d.has("time_domain_check")) {
    if (!d.isSection("time_domain_check"))
      throw InputError(d.where("time_domain_check"), "expects a section, e.g. {periods: 600, steps_per_period: 1024}");
    auto td = d.section("time_domain_check");
    disc::PeakInTimeOptions o;
    o.maxPeriods = td.getInt("periods", o.maxPeriods);
    o.stepsPerPeriod = td.getInt("steps_per_period", o.stepsPerPeriod);
    try {
      disc::checkPeakInTimeOptions(o);
    } catch (const InputError& e) {
      throw InputError(td.where(e.where()), e.problem());
    }
    td.rejectUnknownKeys();
    sweep.peakInTime = o;
  }

  // The band swept in time: asked for by the section, e.g. {preloads: [0, 1000, 20000]}.
  if (d.has("time_domain_sweep")) {
    if (!d.isSection("time_domain_sweep"))
      throw InputError(d.where("time_domain_sweep"), "expects a section, e.g. {band: [1400, 1580], preloads: [0, 2000]}");
    auto ts = d.section("time_domain_sweep");
    disc::SweepInTimeOptions o;
    const auto band = ts.getDoubleList("band", {});
    if (!band.empty() && (band.size() != 2 || !(band[0] > 0) || !(band[1] > band[0])))
      throw InputError(ts.where("band"), "needs two increasing positive frequencies [from, to] in Hz");
    if (!band.empty()) o.fromHz = band[0], o.toHz = band[1];
    o.frequencies = ts.getInt("frequencies", 12);
    if (o.frequencies < 2) throw InputError(ts.where("frequencies"), "must lie in 2..1000 (a band)");
    o.periods = ts.getInt("periods", o.periods);
    o.stepsPerPeriod = ts.getInt("steps_per_period", o.stepsPerPeriod);
    try {  // the library's ranges, under this section's keys
      disc::checkSweepInTimeOptions(o);
    } catch (const InputError& e) {
      throw InputError(ts.where(e.where()), e.problem());
    }
    sweep.sweepPreloads = ts.getDoubleList("preloads", {});
    for (std::size_t i = 0; i < sweep.sweepPreloads.size(); ++i)
      if (!(sweep.sweepPreloads[i] >= 0 && std::isfinite(sweep.sweepPreloads[i])) ||
          (i > 0 && !(sweep.sweepPreloads[i] > sweep.sweepPreloads[i - 1])))
        throw InputError(ts.where("preloads"), "must be >= 0 and increasing (N, as disc_response/contact/preload)");
    ts.rejectUnknownKeys();
    sweep.sweepInTime = o;
  }

  sweep.stability = readStability(d);
  sweep.harmonicsCheckTo = plan.harmonicsCheckTo;
  sweep.harmonicsTolerance = plan.harmonicsTolerance;
  auto cs = d.section("continuation");
  using Engine = continuation::ContinuationOptions::Engine;
  // The disc's defaults for the engine named (an unknown name is refused, naming the key,
  // by readContinuationSteps).
  const std::string byDefault = continuation::engineKey(Engine::PredictorCorrector);
  sweep.continuation = disc::discContinuationOptions(
      continuation::engineFromKey(cs.getString("engine", byDefault)).value_or(Engine::PredictorCorrector));
  if (cs.has("engine")) sweep.fallback.reset();
  readContinuationSteps(cs, sweep.continuation, byDefault);
  sweep.continuation.tolerance = readContinuationTolerance(cs, sweep.continuation.tolerance);
  cs.rejectUnknownKeys();
  sweep.continuation.checkpoints = checkpoints;
  if (sweep.fallback) sweep.fallback->checkpoints = checkpoints;
  return sweep;
}

}  // namespace cyclone::scenes
