// The shroud contact law per unit area keeps the interface the same at any mesh; the law
// per node pair does not (its interface's stiffness and load grow with the number of
// pairs). On the demo's disc (24 sectors, 10 000 rpm, EO 3, 20 N at the mid-blade node,
// a mesh node at the same material point at every size) at mesh sizes 6 and 4 (and 8/3 in
// the slow test, CYCLONE_SLOW_LEVELS=1: the sizes in the ratio 1.5; CYCLONE_MESH_SIZES=a,b,..
// runs others), with each law: per pair kn = kt = 1e4 N/mm and 500 N a pair, per area the
// demo scene's kn = kt = 5000 N/mm^3 and 20 kN over the interface. Two quantities: the
// stuck-shroud resonance (the response linearised at rest, contacts stuck: a linear FE
// quantity) and the friction-damped peak (H = 1: the mesh's effect on one balance, not
// the harmonics'). The shroud-free resonance is the FE mesh's own convergence, the scale
// of what the others should do. Per area, each refinement must change the stuck
// resonance less than per pair does, and so must all of them together; with three
// levels or more, each refinement must change the stuck resonance and the friction-damped
// peak per area less than the one before (the sequence converges), the observed order
// printed. Printed per level: pairs, area, the interface's stiffness, the frequencies and
// peaks per law, the run time.
#include <Tpetra_Core.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "cyclone/core/Log.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/disc/DiscHarmonicBalance.hpp"
#include "cyclone/disc/ShroudContactLaw.hpp"
#include "cyclone/mesh/ShroudedSectorGenerator.hpp"
#include "DemoDisc.hpp"

using namespace cyclone;

namespace {

struct Level {
  double meshSize = 0;
  std::size_t pairs = 0;
  double area = 0, freeHz = 0, stuckPerPair = 0, stuckPerArea = 0, kn = 0, seconds = 0;
  double peakPerPair = 0, peakPerArea = 0;  // the friction-damped peak (H = 1), mm
};

// The demo scene's law per unit area: 5000 N/mm^3, 20 kN over the interface.
constexpr double kStiffnessPerArea = 5000, kInterfaceLoad = 20000;

Level level(double meshSize) {
  Timer timer;
  log::setQuiet(true);
  mesh::ShroudedSectorParameters p;
  p.meshSize = meshSize;
  const auto mesh = mesh::generateShroudedSector(p);
  auto models = demo_disc::demoDiscModels(p);
  models.checkFrequencies = 0;  // the reduced models' own check is not what is measured here
  disc::DiscResponseSpec spec = demo_disc::demoDiscResponse(1);
  const auto reduced = disc::buildDiscReducedModels(mesh, models, disc::nodalDiametersFor(p.sectors, 3, {0, 1}),
                                                    "", Tpetra::getDefaultComm());
  Level out;
  out.meshSize = meshSize;
  auto perPair = disc::makeDiscForcedResponse(mesh, reduced, spec);
  const auto pairEstimate = disc::estimateResonance(perPair, reduced);
  spec.contact.law = disc::ShroudContactSpec::Law::PerArea;
  spec.contact.kn = spec.contact.kt = kStiffnessPerArea;
  spec.contact.preload = kInterfaceLoad;
  const auto pairs = disc::shroudContactPairs(mesh, reduced.sectors, reduced.sector.axis, spec.contact);
  const auto values = disc::shroudContactValues(mesh, pairs, spec.contact);
  out.pairs = values.kn.size(), out.area = values.totalArea, out.kn = values.totalKn;
  auto perArea = disc::makeDiscForcedResponse(mesh, reduced, spec);
  const auto areaEstimate = disc::estimateResonance(perArea, reduced);
  out.freeHz = pairEstimate.freeHz, out.stuckPerPair = pairEstimate.stuckHz, out.stuckPerArea = areaEstimate.stuckHz;
  // The friction-damped peak, H = 1, over 4 % below to 1 % above the stuck resonance.
  auto peak = [&](const disc::DiscResponseSpec& s, double stuckHz) {
    disc::DiscSweepOptions sweep;
    sweep.stability = response::ForcedResponseSetup::Stability::Never;
    sweep.harmonicsCheckTo = -1;
    sweep.fromHz = 0.96 * stuckHz, sweep.toHz = 1.01 * stuckHz;
    const auto c = disc::solveDiscForcedResponse(mesh, reduced, s, sweep);
    EXPECT_TRUE(c.curve.branch.finished) << c.curve.branch.stopReason;
    return c.curve.peak;
  };
  out.peakPerArea = peak(spec, out.stuckPerArea);
  auto pairSpec = demo_disc::demoDiscResponse(1);
  out.peakPerPair = peak(pairSpec, out.stuckPerPair);
  out.seconds = timer.seconds();
  return out;
}

}  // namespace

// The change from each level to the next, and the order the last three levels show
// (sizes in a constant ratio r: d1 / d2 = r^p).
namespace {
double observedOrder(double change1, double change2, double ratio) {
  return std::log(change1 / change2) / std::log(ratio);
}
}  // namespace

TEST(ShroudContactMeshConvergence, PerAreaStuckResonanceAndFrictionPeakConverge) {
  std::vector<double> sizes{6.0, 4.0};
  if (const char* more = std::getenv("CYCLONE_SLOW_LEVELS"); more && std::atoi(more) >= 1) sizes.push_back(8.0 / 3);
  if (const char* list = std::getenv("CYCLONE_MESH_SIZES")) {
    sizes.clear();
    for (char* end = nullptr; *list; list = *end ? end + 1 : end) sizes.push_back(std::strtod(list, &end));
  }
  std::vector<Level> levels;
  for (double h : sizes) {
    levels.push_back(level(h));
    const auto& l = levels.back();
    std::printf("mesh %.3g: %zu pairs over %.4f mm^2; shroud free %.3f Hz; stuck: per pair %.3f Hz "
                "(interface %.4g N/mm), per area %.3f Hz (interface %.4g N/mm); friction-damped peak (H = 1): per "
                "pair %.5f mm, per area %.5f mm; %.1f s\n",
                l.meshSize, l.pairs, l.area, l.freeHz, l.stuckPerPair, l.pairs * 1e4, l.stuckPerArea, l.kn,
                l.peakPerPair, l.peakPerArea, l.seconds);
    std::fflush(stdout);
  }
  // The interface per area is the same at every mesh (its area converges with the face's
  // triangulation: a flat face, so exactly).
  for (const auto& l : levels) EXPECT_NEAR(l.area, levels.front().area, 1e-9 * levels.front().area);
  for (std::size_t i = 1; i < levels.size(); ++i) {
    const auto &a = levels[i - 1], &b = levels[i];
    const double perArea = std::abs(b.stuckPerArea - a.stuckPerArea);
    const double perPair = std::abs(b.stuckPerPair - a.stuckPerPair);
    const double free = std::abs(b.freeHz - a.freeHz);
    std::printf("mesh %.3g -> %.3g: stuck per area changes %.3f Hz, per pair %.3f Hz, shroud free %.3f Hz; the "
                "friction-damped peak per area %.2e, per pair %.2e (relative)\n",
                a.meshSize, b.meshSize, perArea, perPair, free, std::abs(b.peakPerArea / a.peakPerArea - 1),
                std::abs(b.peakPerPair / a.peakPerPair - 1));
    EXPECT_LT(perArea, perPair);
  }
  for (std::size_t i = 2; i < levels.size(); ++i) {
    const auto &a = levels[i - 2], &b = levels[i - 1], &c = levels[i];
    const double stuck1 = std::abs(b.stuckPerArea - a.stuckPerArea), stuck2 = std::abs(c.stuckPerArea - b.stuckPerArea);
    const double peak1 = std::abs(b.peakPerArea - a.peakPerArea), peak2 = std::abs(c.peakPerArea - b.peakPerArea);
    const double ratio = a.meshSize / b.meshSize;
    std::printf("mesh %.3g, %.3g, %.3g per area: the stuck resonance's changes %.3f, %.3f Hz (observed order %.2f), "
                "the friction-damped peak's %.2e, %.2e mm (observed order %.2f)\n",
                a.meshSize, b.meshSize, c.meshSize, stuck1, stuck2, observedOrder(stuck1, stuck2, ratio), peak1,
                peak2, observedOrder(peak1, peak2, ratio));
    EXPECT_LT(stuck2, stuck1);
    EXPECT_LT(peak2, peak1);
  }
  const auto& coarse = levels.front();
  const auto& fine = levels.back();
  const double driftArea = std::abs(fine.stuckPerArea - coarse.stuckPerArea);
  const double driftPair = std::abs(fine.stuckPerPair - coarse.stuckPerPair);
  const double driftFree = std::abs(fine.freeHz - coarse.freeHz);
  std::printf("mesh %.3g -> %.3g: stuck per area %.3f Hz (%.2f %%), per pair %.3f Hz (%.2f %%), shroud free %.3f Hz "
              "(%.2f %%)\n",
              coarse.meshSize, fine.meshSize, driftArea, 100 * driftArea / coarse.stuckPerArea, driftPair,
              100 * driftPair / coarse.stuckPerPair, driftFree, 100 * driftFree / coarse.freeHz);
  EXPECT_LT(driftArea, driftPair);
}
