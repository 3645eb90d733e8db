// Contact patches against every node pair on the demo's disc (24 sectors, 10 000 rpm,
// EO 3, 20 N at the mid-blade node; the demo scene's law per unit area, 5000 N/mm^3 and
// 20 kN over the 43 pairs' 80 mm^2 face): the friction-damped curve with the face split
// into 4, 8, 16 and 32 patches (each one contact on its pairs' mean motion) against the
// curve with every pair a contact, at the same harmonics (0..2) and samples. Printed per
// level: contacts, unknowns, the peak and its frequency, their changes from every pair's,
// the change the run states (the stuck resonance's, DiscForcedResponse::patchesCheck),
// and the run time. Checked: the patched curves converge to every pair's (the peak's
// change shrinks from 4 to 8 to 32 patches; between neighbouring levels the friction-
// damped peak moves among the sampled law's local tops, 1e-3), and so does the stated
// change. The stated change is the stuck system's, not a bound on the friction-damped
// peak's: that was 1.3 to 3.3 times it at H = 1..3 (docs/scenes.md, "Contact patches").
#include <Tpetra_Core.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "cyclone/core/Log.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/disc/DiscForcedResponse.hpp"
#include "cyclone/disc/ShroudContactLaw.hpp"
#include "cyclone/mesh/ShroudedSectorGenerator.hpp"
#include "DemoDisc.hpp"

using namespace cyclone;

TEST(DiscContactPatches, PatchesConvergeToEveryPair) {
  log::setQuiet(true);
  mesh::ShroudedSectorParameters p;
  const auto mesh = mesh::generateShroudedSector(p);
  const int H = 2;
  Timer timer;
  const auto models = demo_disc::demoDiscReducedModels(mesh, p, H, "", Tpetra::getDefaultComm());
  std::printf("reduced models: %.1f s\n", timer.seconds());
  auto spec = demo_disc::demoDiscResponse(H);
  spec.contact.law = disc::ShroudContactSpec::Law::PerArea;
  spec.contact.kn = spec.contact.kt = 5000.0;  // N/mm^3
  spec.contact.preload = 20000.0;              // N over the interface
  disc::DiscSweepOptions sweep;
  sweep.harmonicsCheckTo = -1;
  sweep.stability = response::ForcedResponseSetup::Stability::Never;
  timer.restart();
  const auto every = disc::solveDiscForcedResponse(mesh, models, spec, sweep);
  const double everySeconds = timer.seconds();
  const auto& a = every.curve;
  ASSERT_TRUE(a.branch.end == continuation::BranchEnd::RangeEnd) << a.branch.stopReason;
  std::printf("every pair: %zu contacts, %d unknowns: peak %.6f mm at %.3f Hz, %zu points, %.1f s\n",
              every.setup.system->elements().size(), every.setup.system->numUnknowns(), a.peak,
              a.peakOmega / (2 * M_PI), a.branch.points.size(), everySeconds);
  std::vector<double> errors, stated;
  for (int patches : {4, 8, 16, 32}) {
    auto patched = spec;
    patched.contact.patches = patches;
    timer.restart();
    const auto fewer = disc::solveDiscForcedResponse(mesh, models, patched, sweep);
    const double seconds = timer.seconds();
    const auto& b = fewer.curve;
    ASSERT_TRUE(b.branch.end == continuation::BranchEnd::RangeEnd) << patches << ": " << b.branch.stopReason;
    ASSERT_TRUE(fewer.patchesCheck);
    const auto& c = *fewer.patchesCheck;
    const double amplitude = std::abs(b.peak / a.peak - 1), frequency = std::abs(b.peakOmega / a.peakOmega - 1);
    errors.push_back(amplitude);
    stated.push_back(c.amplitudeChange());
    std::printf("%2d patches: %d unknowns: peak %.6f mm at %.3f Hz (changes %.2e, %.2e), stated %.2e, %.2e; %zu "
                "points, %.1f s\n",
                patches, fewer.setup.system->numUnknowns(), b.peak, b.peakOmega / (2 * M_PI), amplitude, frequency,
                c.amplitudeChange(), c.frequencyChange(), b.branch.points.size(), seconds);
  }
  EXPECT_LT(errors[1], errors[0]) << "8 patches against 4";
  EXPECT_LT(errors[3], errors[1]) << "32 patches against 8";
  for (std::size_t i = 1; i < stated.size(); ++i) EXPECT_LT(stated[i], stated[i - 1]) << "level " << i;
}

// The models retaining each patch's mean motion (two means a patch, DiscModelSpec::
// retainedMeans: a static correction of 6 load cases a patch instead of 3 per face node)
// against the models retaining every face node, the same 8 patches on both: the hybrid
// model is linear in its loads, so the means' receptance is the nodes' seen through the
// patches' weights, and the two friction problems are one. Checked on the condensed
// unknowns (the same coordinates in both: the patches' relative motions and the
// mid-blade's): the residual of one at the other's traced points, and the peaks.
TEST(DiscContactPatches, PatchMeansRetainedAreTheFaceNodesThroughTheirWeights) {
  log::setQuiet(true);
  mesh::ShroudedSectorParameters p;
  const auto mesh = mesh::generateShroudedSector(p);
  const int H = 2;
  auto spec = demo_disc::demoDiscResponse(H);
  spec.contact.law = disc::ShroudContactSpec::Law::PerArea;
  spec.contact.kn = spec.contact.kt = 5000.0;
  spec.contact.preload = 20000.0;
  spec.contact.patches = 8;
  std::vector<int> harmonics;
  for (int h = 0; h <= H; ++h) harmonics.push_back(h);
  const auto nds = disc::nodalDiametersFor(p.sectors, 3, harmonics);
  const auto comm = Tpetra::getDefaultComm();
  Timer timer;
  const auto nodes = disc::buildDiscReducedModels(mesh, demo_disc::demoDiscModels(p), nds, "", comm);
  const double nodeSeconds = timer.seconds();
  auto meanSpec = demo_disc::demoDiscModels(p);
  meanSpec.retainedNodeSets = {"mid_blade"};
  const auto pairs = disc::shroudContactPairs(mesh, p.sectors, nodes.sector.axis, spec.contact);
  meanSpec.retainedMeans = disc::shroudPatchMeans(pairs, disc::shroudContactValues(mesh, pairs, spec.contact), spec.contact);
  ASSERT_EQ(meanSpec.retainedMeans.size(), 16u);
  timer.restart();
  const auto means = disc::buildDiscReducedModels(mesh, meanSpec, nds, "", comm);
  const double meanSeconds = timer.seconds();
  ASSERT_EQ(means.models.at(3)->size(), 2 * 3 * (1 + 16));

  disc::DiscSweepOptions sweep;
  sweep.harmonicsCheckTo = -1;
  sweep.stability = response::ForcedResponseSetup::Stability::Never;
  const auto a = disc::solveDiscForcedResponse(mesh, nodes, spec, sweep);
  const auto b = disc::solveDiscForcedResponse(mesh, means, spec, sweep);
  ASSERT_TRUE(a.curve.branch.end == continuation::BranchEnd::RangeEnd) << a.curve.branch.stopReason;
  ASSERT_TRUE(b.curve.branch.end == continuation::BranchEnd::RangeEnd) << b.curve.branch.stopReason;
  ASSERT_EQ(a.setup.system->numUnknowns(), b.setup.system->numUnknowns());
  double worst = 0;
  Eigen::VectorXd Ra, Rb, R0;
  for (const auto& point : a.curve.branch.points) {
    const double omega = point.parameter * a.setup.omegaUnit;
    a.setup.system->residual(point.x, omega, Ra, nullptr);
    b.setup.system->residual(point.x, omega, Rb, nullptr);
    // Against the residual at rest (the excitation, in the residual's own units).
    a.setup.system->residual(Eigen::VectorXd::Zero(point.x.size()), omega, R0, nullptr);
    worst = std::max(worst, (Rb - Ra).norm() / R0.norm());
  }
  const double peak = std::abs(b.curve.peak / a.curve.peak - 1), hz = std::abs(b.curve.peakOmega / a.curve.peakOmega - 1);
  std::printf("8 patches: models retaining the face nodes %.1f s (%ld DOFs at ND 3), the patch means %.1f s (%ld); "
              "residuals of the means' system at the nodes' %zu points: %.2e; peaks %.6f against %.6f mm (%.1e), "
              "%.3f against %.3f Hz (%.1e)\n",
              nodeSeconds, long(nodes.models.at(3)->size()), meanSeconds, long(means.models.at(3)->size()),
              a.curve.branch.points.size(), worst, b.curve.peak, a.curve.peak, peak, b.curve.peakOmega / (2 * M_PI),
              a.curve.peakOmega / (2 * M_PI), hz);
  EXPECT_LT(worst, 1e-9);
  EXPECT_LT(peak, 1e-6);
  EXPECT_LT(hz, 1e-7);
}
