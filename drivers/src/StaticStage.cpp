// The static analysis of a mesh scene: its problem read (material, constraints, loads,
// solver) and solved, static.exo written.
#include <Teuchos_Comm.hpp>

#include <cmath>
#include <sstream>

#include "cyclone/analysis/StaticAnalysis.hpp"
#include "cyclone/core/Error.hpp"
#include "cyclone/core/NumberText.hpp"
#include "cyclone/core/Log.hpp"
#include "cyclone/scenes/SceneSection.hpp"
#include "SceneStages.hpp"

namespace cyclone::scenes {

analysis::StaticProblem readStaticProblem(SceneSection& scene, const mesh::Mesh& mesh) {
  analysis::StaticProblem problem;
  problem.material = readMaterial(scene.section("material"));
  {
    auto c = scene.section("constraints");
    problem.fixedNodeSets = c.getStringList("fixed_node_sets", {});
    c.rejectUnknownKeys();
    for (const auto& name : problem.fixedNodeSets)
      if (!mesh.nodeSets.count(name)) mesh.nodeSet(name);  // throws naming the mesh and its sets
  }
  readStaticLoads(scene.section("loads"), mesh, problem);
  checkCentrifugalStrain(problem.material, problem.speedRpm, mesh, problem.axis, scene.where("loads/speed_rpm"),
                         scene.where("mesh"));
  readStaticSolver(scene.section("solver"), problem);
  if (problem.fixedNodeSets.empty())
    throw InputError(scene.where("constraints/fixed_node_sets"),
                     "a static analysis needs fixed node sets (the model would move as a rigid body)");
  return problem;
}

void readStaticSolver(SceneSection s, analysis::StaticProblem& problem) {
  problem.solver.kind = solvers::linearSolverKindFromName(s.getString("type", "direct"), s.where("type"));
  problem.solver.tolerance = s.getDouble("tolerance", problem.solver.tolerance);
  problem.solver.maxIterations = s.getInt("max_iterations", problem.solver.maxIterations);
  s.rejectUnknownKeys();
}

void readStaticLoads(SceneSection l, const mesh::Mesh& mesh, analysis::StaticProblem& problem) {
  problem.speedRpm = l.getDouble("speed_rpm", 0.0);
  if (!(problem.speedRpm >= 0 && std::isfinite(problem.speedRpm)))
    throw InputError(l.where("speed_rpm"), numberText(problem.speedRpm) +
                                               ": must be >= 0 and finite (the centrifugal load does not depend on "
                                               "the sense of rotation: give its magnitude)");
  problem.axis = readRotationAxis(l);
  const auto b = l.getVector3("body_force", {0, 0, 0});
  problem.bodyForce = Eigen::Vector3d(b[0], b[1], b[2]);
  auto forces = l.section("nodal_forces");
  for (const auto& name : forces.sectionNames()) {
    auto f = forces.section(name);
    analysis::NodalForce load;
    load.nodeSet = f.getString("node_set", "");
    const auto v = f.getVector3("force", {0, 0, 0});
    load.forcePerNode = Eigen::Vector3d(v[0], v[1], v[2]);
    f.rejectUnknownKeys();
    mesh.nodeSet(load.nodeSet);
    problem.nodalForces.push_back(load);
  }
  forces.rejectUnknownKeys();
  l.rejectUnknownKeys();
}

void staticStage(const analysis::StaticProblem& problem, const mesh::Mesh& mesh, const std::string& outDir,
                 linalg::CommPtr comm, SceneSummary& summary) {
  {
    std::ostringstream msg;
    msg << "linear static analysis at " << problem.speedRpm << " rpm";
    log::info(msg.str());
  }
  const auto result = analysis::solveStatic(mesh, problem, comm);
  const std::string path = outDir + "/static.exo";
  if (comm->getRank() == 0) analysis::writeStaticResult(path, mesh, result);
  std::ostringstream line;
  line << "static: " << result.equations << " equations, max |u| = " << result.maxDisplacement << " at node "
       << (result.maxDisplacementNode >= 0 ? mesh.nodeIds[result.maxDisplacementNode] : -1)
       << ", max von Mises = " << result.maxVonMises << ", residual " << result.solve.relativeResidual;
  summary.computed.push_back(line.str());
  summary.written.push_back(path);
}

}  // namespace cyclone::scenes
