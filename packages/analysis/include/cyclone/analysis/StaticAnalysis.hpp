#pragma once
// Linear static analysis of a mesh: fixed node sets, centrifugal, body and
// nodal loads, one solve, stresses; the library call behind a static scene.
#include <array>
#include <string>
#include <vector>

#include "cyclone/fe/Assembler.hpp"
#include "cyclone/fe/StressRecovery.hpp"
#include "cyclone/solvers/LinearSolver.hpp"

namespace cyclone::analysis {

struct NodalForce {
  std::string nodeSet;
  Eigen::Vector3d forcePerNode = Eigen::Vector3d::Zero();
};

struct StaticProblem {
  fe::IsotropicElastic material;
  std::vector<std::string> fixedNodeSets;
  double speedRpm = 0;  ///< centrifugal load (undeformed geometry, no spin softening: linear)
  mesh::RotationAxis axis;
  Eigen::Vector3d bodyForce = Eigen::Vector3d::Zero();  ///< force per volume
  std::vector<NodalForce> nodalForces;
  solvers::LinearSolveOptions solver;
};

struct StaticResult {
  std::vector<std::array<double, 3>> displacement;  ///< per node, every rank
  fe::StressField stress;
  long long equations = 0;
  double totalLoadNorm = 0;  ///< |sum of the assembled load over the free DOFs per direction|
  double maxDisplacement = 0;
  mesh::Index maxDisplacementNode = -1;
  double maxVonMises = 0;
  double assemblySeconds = 0;
  solvers::LinearSolveReport solve;
};

/// Throws InputError for unknown node sets or an unconstrained model.
StaticResult solveStatic(const mesh::Mesh& mesh, const StaticProblem& problem, linalg::CommPtr comm);

/// Exodus file with nodal ux, uy, uz, von_mises and element stresses s_xx..s_xy and
/// von_mises, one step at time 0 (written by rank 0, atomically).
void writeStaticResult(const std::string& path, const mesh::Mesh& mesh, const StaticResult& result);

}  // namespace cyclone::analysis
