#pragma once
// Monte Carlo over mistuning patterns: per pattern the amplification factor (the largest
// blade peak over the tuned peak), and its statistics over the patterns: mean, 95th and
// 99th percentiles (with a distribution-free 95 % confidence interval from the order
// statistics), and the largest. Any ring whose blade peaks a pattern gives (PatternPeaks):
// the lumped ring, the disc's mistuned ring of reduced sectors (MistunedRingSweep.hpp).
#include <cstdint>
#include <functional>
#include <vector>

#include "cyclone/mistuning/LumpedRing.hpp"

namespace cyclone::mistuning {

struct Percentile {
  double level = 0;         ///< 0.95, 0.99
  double value = 0;         ///< the sample percentile (nearest rank)
  double lower = 0, upper = 0;  ///< a 95 % confidence interval from the order statistics (binomial)
};

struct AmplificationStatistics {
  std::vector<double> factors;  ///< per pattern, in the order drawn
  double mean = 0, largest = 0;
  Percentile p95, p99;
  double tunedPeak = 0;  ///< the tuned blade peak over the same sweep
  std::vector<double> localisation;  ///< per pattern, the inverse participation ratio at its worst peak
  double meanLocalisation = 0;
};

/// A ring's blade peaks over its sweep for a pattern of deviations (the tuned ring for all
/// zero): what the statistics need of a ring, lumped (bladePeaks) or of reduced sectors
/// (MistunedRingSweep::peaks).
using PatternPeaks = std::function<BladePeaks(const std::vector<double>& delta)>;

/// `patterns` random patterns of `blades` deviations of standard deviation `sigma` (seeds
/// seed, seed + 1, ...), each pattern's largest blade peak over the tuned one.
AmplificationStatistics monteCarloAmplification(int blades, const PatternPeaks& peaks, double sigma, int patterns,
                                                std::uint64_t seed);

/// `patterns` random patterns of standard deviation `sigma` (seeds seed, seed + 1, ...),
/// each ring's blade peaks over `omegas` against the tuned peak over the same sweep.
AmplificationStatistics monteCarloAmplification(const LumpedRing& ring, double sigma, int patterns,
                                                std::uint64_t seed, const std::vector<double>& omegas);

/// The percentile at `level` of `values` (nearest rank) and its confidence interval.
Percentile percentileOf(std::vector<double> values, double level);

}  // namespace cyclone::mistuning
