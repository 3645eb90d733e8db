// Example 0: the built-in sector spinning at 10 000 rpm, its bore held: one static
// solve of the centrifugal load.
//   example_static_solve
#include <cstdio>

#include "cyclone/analysis/StaticAnalysis.hpp"
#include "cyclone/fe/Environment.hpp"
#include "cyclone/mesh/ShroudedSectorGenerator.hpp"

int main(int argc, char** argv) {
  cyclone::Environment env(argc, argv);
  cyclone::mesh::ShroudedSectorParameters sector;
  sector.meshSize = 10.0;
  const auto mesh = cyclone::mesh::generateShroudedSector(sector);

  cyclone::analysis::StaticProblem problem;  // titanium, z axis
  problem.fixedNodeSets = {"bore"};
  problem.speedRpm = 10000;
  const auto result = cyclone::analysis::solveStatic(mesh, problem, env.comm());
  std::printf("static solve: %lld equations, max |u| = %g, residual %g\n", result.equations, result.maxDisplacement,
              result.solve.relativeResidual);
  return result.solve.relativeResidual < 1e-8 && result.maxDisplacement > 0 ? 0 : 1;
}
