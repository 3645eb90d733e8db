#include "cyclone/analysis/StaticAnalysis.hpp"

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>

#include <cmath>
#include <sstream>

#include "cyclone/core/Error.hpp"
#include "cyclone/core/Log.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/mesh/ExodusIO.hpp"

namespace cyclone::analysis {

StaticResult solveStatic(const mesh::Mesh& mesh, const StaticProblem& problem, linalg::CommPtr comm) {
  problem.material.validate("material");
  StaticResult result;
  Timer timer;
  fe::DofMap dofs(mesh.numNodes());
  for (const auto& name : problem.fixedNodeSets) dofs.constrain(mesh.nodeSet(name));
  dofs.finalize();
  result.equations = dofs.numFree();
  fe::Assembler assembler(mesh, dofs, comm);
  auto K = assembler.stiffness(problem.material);
  auto f = Teuchos::rcp(new linalg::MultiVector(assembler.map(), 1));
  if (problem.speedRpm != 0) {
    const double omega = problem.speedRpm * 2 * M_PI / 60;
    f->update(1.0, *assembler.centrifugalLoad(problem.material, omega, problem.axis), 1.0);
  }
  if (problem.bodyForce.norm() > 0) f->update(1.0, *assembler.bodyLoad(problem.bodyForce), 1.0);
  for (const auto& load : problem.nodalForces)
    f->update(1.0, *assembler.nodalLoad(mesh.nodeSet(load.nodeSet), load.forcePerNode), 1.0);
  result.totalLoadNorm = f->getVector(0)->norm2();
  result.assemblySeconds = timer.seconds();
  {
    std::ostringstream msg;
    msg << "assembled " << result.equations << " equations (" << K->getGlobalNumEntries() << " nonzeros) in "
        << result.assemblySeconds << " s";
    log::info(msg.str());
  }
  if (result.totalLoadNorm == 0) log::warn("static analysis: the load is zero; the solution will be zero");

  linalg::MultiVector u(assembler.map(), 1);
  auto options = problem.solver;
  if (options.kind == solvers::LinearSolverKind::Iterative && options.nearNullSpace.is_null())
    options.nearNullSpace = assembler.rigidBodyModes();
  result.solve = solvers::solveLinear(*K, *f, u, options);
  {
    std::ostringstream msg;
    msg << "solved (" << (options.kind == solvers::LinearSolverKind::Direct ? "CHOLMOD" : "CG + MueLu") << "): "
        << "setup " << result.solve.setupSeconds << " s, solve " << result.solve.solveSeconds
        << " s, relative residual " << result.solve.relativeResidual;
    if (result.solve.iterations) msg << ", " << result.solve.iterations << " iterations";
    log::info(msg.str());
  }
  result.displacement = assembler.nodalField(u);
  result.stress = fe::recoverStresses(assembler, problem.material, result.displacement);
  for (mesh::Index n = 0; n < mesh.numNodes(); ++n) {
    const auto& d = result.displacement[n];
    const double m = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    if (m > result.maxDisplacement) result.maxDisplacement = m, result.maxDisplacementNode = n;
  }
  for (double s : result.stress.elementVonMises) result.maxVonMises = std::max(result.maxVonMises, s);
  return result;
}

void writeStaticResult(const std::string& path, const mesh::Mesh& mesh, const StaticResult& result) {
  mesh::ExodusResults out;
  out.nodalNames = {"ux", "uy", "uz", "von_mises"};
  out.elementNames = {"s_xx", "s_yy", "s_zz", "s_yz", "s_xz", "s_xy", "von_mises"};
  mesh::ExodusResults::Step step;
  step.time = 0.0;
  step.nodal.assign(4, std::vector<double>(mesh.numNodes()));
  for (mesh::Index n = 0; n < mesh.numNodes(); ++n) {
    for (int d = 0; d < 3; ++d) step.nodal[d][n] = result.displacement[n][d];
    step.nodal[3][n] = result.stress.nodalVonMises[n];
  }
  step.element.assign(7, std::vector<double>(mesh.numElements()));
  for (mesh::Index e = 0; e < mesh.numElements(); ++e) {
    for (int k = 0; k < 6; ++k) step.element[k][e] = result.stress.elementStress[e][k];
    step.element[6][e] = result.stress.elementVonMises[e];
  }
  out.steps.push_back(std::move(step));
  mesh::writeExodus(path, mesh, out);
}

}  // namespace cyclone::analysis
