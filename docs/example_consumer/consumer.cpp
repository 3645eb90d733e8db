// Generates a coarse built-in sector, fixes the bore, applies the centrifugal
// load and solves: the library calls an engineering code makes.
#include <Tpetra_Core.hpp>

#include <cstdio>

#include "cyclone/analysis/StaticAnalysis.hpp"
#include "cyclone/mesh/ShroudedSectorGenerator.hpp"

int main(int argc, char** argv) {
  Tpetra::ScopeGuard mpi(&argc, &argv);
  cyclone::mesh::ShroudedSectorParameters sector;
  sector.meshSize = 10.0;
  const auto mesh = cyclone::mesh::generateShroudedSector(sector);

  cyclone::analysis::StaticProblem problem;  // titanium, z axis
  problem.fixedNodeSets = {"bore"};
  problem.speedRpm = 10000;
  const auto result = cyclone::analysis::solveStatic(mesh, problem, Tpetra::getDefaultComm());
  std::printf("consumer: %lld equations, max |u| = %g, residual %g\n", result.equations, result.maxDisplacement,
              result.solve.relativeResidual);
  return result.solve.relativeResidual < 1e-8 && result.maxDisplacement > 0 ? 0 : 1;
}
