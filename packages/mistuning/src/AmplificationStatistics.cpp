#include "cyclone/mistuning/AmplificationStatistics.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "cyclone/core/Error.hpp"
#include "cyclone/mistuning/MistuningPattern.hpp"

namespace cyclone::mistuning {

namespace {

// P(Binomial(n, p) <= k), summed in logs (n up to tens of thousands).
double binomialCdf(int n, double p, int k) {
  double sum = 0;
  for (int i = 0; i <= k; ++i)
    sum += std::exp(std::lgamma(n + 1.0) - std::lgamma(i + 1.0) - std::lgamma(n - i + 1.0) + i * std::log(p) +
                    (n - i) * std::log1p(-p));
  return sum;
}

}  // namespace

Percentile percentileOf(std::vector<double> values, double level) {
  if (values.empty()) throw InputError("patterns", "no values for a percentile");
  if (!(level > 0 && level < 1)) throw InputError("percentile", "must lie in (0, 1)");
  std::sort(values.begin(), values.end());
  const int n = int(values.size());
  Percentile p;
  p.level = level;
  p.value = values[std::size_t(std::clamp(int(std::ceil(level * n)) - 1, 0, n - 1))];
  // The order statistics (j, k) with P(x_(j) <= q < x_(k)) >= 95 %: the largest j whose
  // lower tail is within 2.5 %, the smallest k whose upper tail is (the ends where none).
  int j = 0, k = n - 1;
  for (int i = 0; i < n; ++i)
    if (binomialCdf(n, level, i) <= 0.025) j = i + 1;
  for (int i = n - 1; i >= 0; --i)
    if (binomialCdf(n, level, i) >= 0.975) k = i;
  p.lower = values[std::size_t(std::clamp(j - 1, 0, n - 1))];
  p.upper = values[std::size_t(std::clamp(k, 0, n - 1))];
  return p;
}

AmplificationStatistics monteCarloAmplification(int blades, const PatternPeaks& peaks, double sigma, int patterns,
                                                std::uint64_t seed) {
  if (patterns < 1) throw InputError("patterns", "must be at least 1");
  AmplificationStatistics out;
  out.tunedPeak = peaks(std::vector<double>(std::size_t(blades), 0.0)).largest();
  for (int i = 0; i < patterns; ++i) {
    const auto p = peaks(randomPattern(blades, sigma, seed + std::uint64_t(i)));
    out.factors.push_back(p.largest() / out.tunedPeak);
    out.localisation.push_back(p.localisation);
  }
  double sum = 0, ipr = 0;
  for (int i = 0; i < patterns; ++i)
    sum += out.factors[std::size_t(i)], ipr += out.localisation[std::size_t(i)],
        out.largest = std::max(out.largest, out.factors[std::size_t(i)]);
  out.mean = sum / patterns;
  out.meanLocalisation = ipr / patterns;
  out.p95 = percentileOf(out.factors, 0.95);
  out.p99 = percentileOf(out.factors, 0.99);
  return out;
}

AmplificationStatistics monteCarloAmplification(const LumpedRing& ring, double sigma, int patterns,
                                                std::uint64_t seed, const std::vector<double>& omegas) {
  return monteCarloAmplification(
      ring.blades, [&](const std::vector<double>& delta) { return bladePeaks(ring, delta, omegas); }, sigma, patterns,
      seed);
}

}  // namespace cyclone::mistuning
