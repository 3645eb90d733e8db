#pragma once
// The friction-damped response swept in the time domain: the ring of reduced sectors
// (hbm::integrateTravellingWave) integrated at a row of frequencies across a band, each
// from the previous one's end (the first from rest), upwards as a sine-sweep test runs;
// and that sweep at several preloads, with the preload whose largest amplitude is the
// smallest (the optimum preload) marked.
//
// Why: where the shroud hammers (every pair opening each period) the periodic response
// near the resonance is unstable (a complex pair of Floquet exponents) and the disc's
// motion is modulated: no harmonic count of the harmonic balance gives its amplitude,
// and on the default disc that is where the optimum preload lies
// (docs/studies/hammering_preload_time_domain.md). The time domain keeps every harmonic
// and follows whatever the motion does; its cost is that of a test rig's stepped sine,
// periods per frequency times frequencies (minutes per preload on the default disc).
//
// Per frequency the amplitude is max |x(t)| of the output DOF: where the run settles,
// its last period's; where it does not within `periods`, the range (largest and
// smallest per period) over the last quarter of the run, at least 50 periods. The
// sweep's amplitude is the largest over the band; the frequency grid's step is its
// resolution, said beside it.
#include <functional>
#include <string>
#include <vector>

#include "cyclone/disc/DiscHarmonicBalance.hpp"
#include "cyclone/hbm/TravellingWaveIntegration.hpp"

namespace cyclone::response {
struct ForcedResponseSetup;
}

namespace cyclone::disc {

/// How the band is swept; every field has the scenes' default.
struct SweepInTimeOptions {
  double fromHz = 0, toHz = 0;  ///< the band (both > 0, from < to; from = to for one frequency)
  int frequencies = 9;          ///< evenly spaced over the band, ends included
  int periods = 300;            ///< the most integrated at one frequency (>= 100; the first, from rest, twice)
  int stepsPerPeriod = 256;     ///< raised to the central difference's stability limit where it needs more
  double residualHz = 50000;    ///< the hybrid models' static correction realized by modes at this frequency
  double amplitudeTolerance = 1e-3;  ///< steady where the amplitude stayed within this over 50 periods
};

/// One frequency of a sweep.
struct SweepInTimePoint {
  double hz = 0;
  hbm::TravellingWaveResponse::Ending ending = hbm::TravellingWaveResponse::Ending::NotSteady;
  int periods = 0;
  double largest = 0, smallest = 0;  ///< max |x(t)| per period: steady, both the last period's
  double seconds = 0;
  bool steady() const { return ending != hbm::TravellingWaveResponse::Ending::NotSteady; }
};

/// A band swept in time at one set of contact values.
struct SweepInTime {
  double preload = 0;  ///< the contact law's (N: per pair, or over the face for the per-area law)
  std::vector<SweepInTimePoint> points;
  int stepsPerPeriod = 0, sectors = 0;
  double seconds = 0;
  /// The point with the largest amplitude; its largest is the sweep's.
  std::size_t largestIndex() const;
  double largest() const { return points.empty() ? 0 : points[largestIndex()].largest; }
  /// The grid's step (Hz): where the amplitude is largest the resonance lies within it.
  double resolutionHz() const;
  /// The largest amplitude at the band's first or last frequency: the resonance may lie outside.
  bool largestAtBandEnd() const;
  std::string text() const;  ///< one line: the largest amplitude, where, steady or its range
};

/// The options' ranges, before any work: InputError whose `where` is the scene key under
/// disc_response/time_domain_sweep (band, frequencies, periods, steps_per_period); a band
/// of 0, 0 (the caller's default, set later) passes.
void checkSweepInTimeOptions(const SweepInTimeOptions& options);

/// The band swept in time on setup's system (a disc's: makeDiscForcedResponse); `sectors`
/// and `engineOrder` give the phases the excitation and contacts reach. `progress` (may
/// be empty) is told each frequency's point as it is done. InputError naming
/// disc_response/time_domain_sweep where the system has no modes (a full FE or matrix
/// system) or the options are out of range.
SweepInTime sweepInTime(const response::ForcedResponseSetup& setup, long sectors, int engineOrder,
                        const SweepInTimeOptions& options,
                        const std::function<void(const SweepInTimePoint&)>& progress = {});

/// The sweep at each preload, and the optimum: the preload whose largest amplitude is the
/// smallest.
struct PreloadSweepsInTime {
  std::vector<SweepInTime> sweeps;  ///< in the preloads' order (increasing)
  int optimum = -1;                 ///< index into sweeps (-1: none swept)
  /// The optimum has a preload on each side whose amplitude is larger: located inside the range.
  bool optimumInside() const { return optimum > 0 && optimum + 1 < int(sweeps.size()); }
  double seconds = 0;
  std::string text() const;  ///< the summary's line
};

/// `preloads` increasing and >= 0; each sweep on spec with that preload.
PreloadSweepsInTime sweepPreloadsInTime(const mesh::Mesh& mesh, const DiscReducedModels& models,
                                        const DiscResponseSpec& spec, const std::vector<double>& preloads,
                                        const SweepInTimeOptions& options,
                                        const std::function<void(const SweepInTimePoint&)>& progress = {});

}  // namespace cyclone::disc
