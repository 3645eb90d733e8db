// Example 2: the Campbell and SAFE diagrams of the built-in sector over 0..10 000 rpm,
// and the engine-order resonances in that range.
//   example_campbell_safe   (writes campbell.svg, safe.svg, resonances.csv)
#include <cmath>
#include <cstdio>
#include <vector>

#include "cyclone/cyclic/ModalSweep.hpp"
#include "cyclone/fe/Environment.hpp"
#include "cyclone/mesh/ShroudedSectorGenerator.hpp"
#include "cyclone/post/CampbellDiagram.hpp"

using namespace cyclone;

int main(int argc, char** argv) {
  Environment env(argc, argv);

  // 1. The sector: the built-in shrouded sector of a 24-sector disc, coarse.
  mesh::ShroudedSectorParameters p;
  p.meshSize = 12.0;
  const auto mesh = mesh::generateShroudedSector(p);
  const auto sector = cyclic::makeCyclicSector(mesh, p.sectors, mesh::RotationAxis{{0, 0, 0}, {0, 0, 1}},
                                               {"disc_left", "shroud_left"}, {"disc_right", "shroud_right"});

  // 2. Two modes per nodal diameter at three speeds, each on its linear prestress
  //    (stress stiffening and spin softening), the bore held.
  cyclic::ModalSweepProblem sweep;
  sweep.modes.fixedNodeSets = {"bore"};
  sweep.modes.modesPerNodalDiameter = 2;
  sweep.speedsRpm = {0.0, 5000.0, 10000.0};
  sweep.prestress = cyclic::PrestressKind::Linear;
  const auto speeds = cyclic::solveModalSweep(mesh, sector, sweep, env.comm());

  // 3. Families tracked across the speeds by MAC; where engine orders 1..24 cross them.
  std::vector<int> engineOrders;
  for (int eo = 1; eo <= p.sectors; ++eo) engineOrders.push_back(eo);
  const auto branches = post::trackFamilies(speeds);
  const auto resonances = post::findResonances(branches, p.sectors, engineOrders);
  post::writeCampbellSvg("campbell.svg", branches, engineOrders, resonances);
  post::writeSafeSvg("safe.svg", branches, p.sectors, engineOrders, resonances);
  post::writeResonancesCsv("resonances.csv", resonances);

  // 4. What must hold: each resonance lies on its engine order's line f = EO rpm / 60,
  //    and the blade-dominated first family at ND 12 stiffens with speed.
  bool ok = !resonances.empty();
  for (const auto& r : resonances) {
    std::printf("EO %2d  ND %2d  family %d  %7.0f rpm  %8.2f Hz\n", r.engineOrder, r.nd, r.family, r.rpm, r.freqHz);
    ok = ok && std::abs(r.freqHz - r.engineOrder * r.rpm / 60) < 1e-9 * r.freqHz;
  }
  for (const auto& b : branches)
    if (b.nd == 12 && b.family == 1) {
      std::printf("ND 12 family 1: %.2f Hz at 0 rpm, %.2f Hz at 10000 rpm\n", b.freqHz.front(), b.freqHz.back());
      ok = ok && b.freqHz.back() > b.freqHz.front();
    }
  std::printf("%s\n", ok ? "campbell and safe: ok" : "campbell and safe: FAILED");
  return ok ? 0 : 1;
}
