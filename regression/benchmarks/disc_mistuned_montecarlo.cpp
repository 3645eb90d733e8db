// Benchmark (a program, not a test): the linear Monte Carlo of the disc's mistuned ring by
// the subset of nominal modes (issue 51, item 4; mistuning/MistunedRingSweep.hpp). The
// built-in shrouded sector with hybrid models of every nodal diameter at the mid-blade node
// (10 modes each, at rest, cantilever): the small disc of the ring verifications (N = 8,
// mesh size 14, thin disc) or the default disc (24 sectors, mesh size 6; its models cached
// in the cache directory). Engine order 3, a unit axial force on every mid-blade node
// delayed by j 2 pi EO / N, structural damping; the sweep across the first family's band
// (its lowest mode of every nodal diameter, 2 % either side). Each pattern: N Young's
// modulus deviations of standard deviation sigma (seeds 1, 2, ...), every blade's peak,
// the amplification factor against the tuned peak over the same sweep. Prints the set-up
// times, the patterns, the time and time per pattern, mean, 95th and 99th percentiles
// (with their 95 % confidence intervals), the largest, Whitehead's bound and the mean
// inverse participation ratio.
//   build/regression/disc_mistuned_montecarlo [small|default (small)] [patterns (1000)]
//                                             [sigma (0.01)] [frequencies (400)]
//                                             [cache dir (disc_mistuned_models)]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "cyclone/fe/Environment.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/mesh/ShroudedSectorGenerator.hpp"
#include "cyclone/mistuning/AmplificationStatistics.hpp"
#include "cyclone/mistuning/DiscMistunedRing.hpp"
#include "cyclone/mistuning/MistunedRingSweep.hpp"
#include "cyclone/mistuning/ReducedSectorRing.hpp"
#include "SmallRingDisc.hpp"

using namespace cyclone;

int main(int argc, char** argv) {
  Environment env(argc, argv);
  const std::string which = argc > 1 ? argv[1] : "small";
  const int patterns = argc > 2 ? std::atoi(argv[2]) : 1000;
  const double sigma = argc > 3 ? std::atof(argv[3]) : 0.01;
  const int points = argc > 4 ? std::atoi(argv[4]) : 400;
  const std::string cache = argc > 5 ? argv[5] : "disc_mistuned_models";
  const int eo = 3;

  mesh::ShroudedSectorParameters geometry;
  if (which == "small") geometry = regression::smallRingGeometry(8);
  const int N = geometry.sectors;
  const auto mesh = mesh::generateShroudedSector(geometry);
  const auto spec = regression::smallRingModelSpec(N, {"mid_blade"});
  Timer t;
  const auto models = disc::buildDiscReducedModels(mesh, spec, mistuning::everyNodalDiameter(N),
                                                   which == "small" ? "" : cache, env.comm());
  const double romSeconds = t.seconds();
  t.restart();
  const auto nominal = mistuning::discNominalModes(mesh, models, spec, env.comm());
  const auto blade = mistuning::bladeElementsAboveRadius(mesh, spec.axis, geometry.rimRadius);
  const auto ring = mistuning::makeDiscMistunedRing(
      mesh, nominal, spec.material, blade, mistuning::youngsModulusFactors(std::vector<double>(N, 1.0), N));
  const auto tuned = *ring.tuned->modalRealization(0);
  const double snmSeconds = t.seconds();
  t.restart();
  const mistuning::MistunedRingSweep sweep(tuned, N, ring.tuned->sectorDofs(), ring.modesPerPhase,
                                           ring.bladeProjection, eo, 2, 2);
  const double sweepSeconds = t.seconds();

  // The first family's band: the lowest mode of every phase.
  double lo = 1e300, hi = 0;
  for (int p = 0, first = 0; p < N; first += ring.modesPerPhase[std::size_t(p)], ++p)
    lo = std::min(lo, tuned.eigenvalues(first)), hi = std::max(hi, tuned.eigenvalues(first));
  lo = 0.98 * std::sqrt(lo), hi = 1.02 * std::sqrt(hi);
  std::vector<double> omegas;
  for (int k = 0; k < points; ++k) omegas.push_back(lo + (hi - lo) * k / (points - 1));

  std::printf("%s disc: N %d, mesh size %g, EO %d, %d ring modes, %d retained DOFs, eta %g\n", which.c_str(), N,
              geometry.meshSize, eo, tuned.numModes(), int(tuned.U.rows()), tuned.lossFactor);
  std::printf("set-up: reduced models %.1f s, full shapes and blade projection %.1f s, sweep's blade matrices %.2f s\n",
              romSeconds, snmSeconds, sweepSeconds);
  std::printf("sweep: %d frequencies, %.2f .. %.2f Hz\n", points, lo / (2 * M_PI), hi / (2 * M_PI));
  t.restart();
  const auto stats = mistuning::monteCarloAmplification(
      N, [&](const std::vector<double>& d) { return sweep.peaks(d, omegas); }, sigma, patterns, 1);
  const double mcSeconds = t.seconds();
  std::printf("patterns %d, sigma %g: %.2f s, %.2f ms a pattern (one core)\n", patterns, sigma, mcSeconds,
              1e3 * mcSeconds / patterns);
  std::printf("amplification: mean %.4f, p95 %.4f [%.4f, %.4f], p99 %.4f [%.4f, %.4f], largest %.4f; Whitehead %.4f\n",
              stats.mean, stats.p95.value, stats.p95.lower, stats.p95.upper, stats.p99.value, stats.p99.lower,
              stats.p99.upper, stats.largest, mistuning::whiteheadBound(N));
  std::printf("localisation: mean inverse participation ratio %.4f (tuned travelling wave 1/N = %.4f)\n",
              stats.meanLocalisation, 1.0 / N);
  return stats.largest < mistuning::whiteheadBound(N) ? 0 : 1;
}
