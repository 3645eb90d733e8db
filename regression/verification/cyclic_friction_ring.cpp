// Verification: the engine-order cyclic constraint on a bladed ring with
// friction between neighbouring tips (scene cyclic_friction_ring.yaml). The
// curve of one cyclic sector is traced; then the full ring of N sectors (all
// N n DOFs, a contact element between every pair of neighbours, the travelling
// wave applied sector by sector) is traced with no cyclic reduction, and every
// ring point is compared with the sector's solution at its frequency, for
// several engine orders (incl. 0 and N/2) and normal preloads.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "cyclone/continuation/NewtonSolve.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/hbm/FrictionContact.hpp"
#include "cyclone/hbm/FullRingSystem.hpp"
#include "cyclone/hbm/HarmonicRefinement.hpp"
#include "cyclone/response/ForcedResponseTrace.hpp"
#include "cyclone/scenes/ForcedResponseScene.hpp"

using namespace cyclone;

namespace {

// The scene's system with another engine order and preload.
std::unique_ptr<hbm::HarmonicBalanceSystem> variant(const hbm::HarmonicBalanceSystem& s, int eo, double preload) {
  auto out = std::make_unique<hbm::HarmonicBalanceSystem>(s.M(), s.C(), s.K(), s.aft().harmonics(),
                                                          s.aft().numSamples());
  auto coupling = s.cyclic();
  coupling.engineOrder = eo;
  out->setCyclic(coupling);
  for (const auto& c : s.elements()) {
    auto p = dynamic_cast<const hbm::FrictionContact&>(*c.element).parameters();
    p.preload = preload;
    out->addElement(std::make_shared<hbm::FrictionContact>(p), c.W, c.Wnext);
  }
  out->addExcitationCoefficients(s.excitation());
  return out;
}

}  // namespace

TEST(CyclicFrictionRing, SectorCurveEqualsFullRingCurve) {
  const auto setup = scenes::loadForcedResponseScene(CYCLONE_SCENE_DIR "/cyclic_friction_ring.yaml");
  const int N = setup.system->cyclic().sectors;
  ASSERT_EQ(setup.system->cyclic().engineOrder, 3);
  for (auto [eo, preload] : {std::pair{3, 0.4}, std::pair{3, 2.0}, std::pair{5, 0.4}, std::pair{0, 0.4},
                             std::pair{N / 2, 0.4}}) {
    const auto sector = variant(*setup.system, eo, preload);
    const auto ring = hbm::expandToFullRing(*sector);
    auto options = setup.continuation;
    options.maxStep = 1.0;
    options.initialStep = 0.1;
    Timer timer;
    const auto sectorProblem = response::continuationProblem(*sector, response::ForcedResponseSetup::Parameter::Omega);
    const auto sectorBranch = continuation::traceBranch(sectorProblem, sector->linearizedSolution(options.from), options);
    const double tSector = timer.seconds();
    timer.restart();
    const auto ringProblem = response::continuationProblem(*ring, response::ForcedResponseSetup::Parameter::Omega);
    const auto ringBranch = continuation::traceBranch(ringProblem, ring->linearizedSolution(options.from), options);
    const double tRing = timer.seconds();
    ASSERT_TRUE(sectorBranch.finished) << sectorBranch.stopReason;
    ASSERT_TRUE(ringBranch.finished) << ringBranch.stopReason;
    // Each ring point against the sector solved at the ring point's frequency
    // (Newton from the nearest sector point of the traced curve).
    double worst = 0, peakRing = 0, peakSector = 0;
    for (const auto& rp : ringBranch.points) {
      std::size_t near = 0;
      for (std::size_t i = 0; i < sectorBranch.points.size(); ++i)
        if (std::abs(sectorBranch.points[i].parameter - rp.parameter) <
            std::abs(sectorBranch.points[near].parameter - rp.parameter))
          near = i;
      Eigen::VectorXd X = sectorBranch.points[near].x;
      ASSERT_TRUE(continuation::solveNewton(sectorProblem, X, rp.parameter, 1e-11).converged);
      const Eigen::VectorXd expanded = hbm::ringCoefficients(*sector, X);
      worst = std::max(worst, (expanded - rp.x).norm() / rp.x.norm());
      peakRing = std::max(peakRing, ring->amplitude(rp.x, 1, 1));
      peakSector = std::max(peakSector, sector->amplitude(X, 1, 1));
    }
    std::printf("EO %d (harmonic 1 on ND %d), preload %.1f: sector %zu points in %.2f s (%d unknowns); ring %zu "
                "points in %.2f s (%d unknowns); max relative difference %.1e; tip peak %.5f vs %.5f\n",
                eo, sector->nodalDiameter(1), preload, sectorBranch.points.size(), tSector, sector->numUnknowns(),
                ringBranch.points.size(), tRing, ring->numUnknowns(), worst, peakSector, peakRing);
    EXPECT_LT(worst, 1e-6);  // both solved to ||R|| < 1e-10 (absolute), the ring with 12x the unknowns
  }
}
