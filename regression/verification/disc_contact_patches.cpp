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
