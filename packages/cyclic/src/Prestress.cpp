#include "cyclone/cyclic/Prestress.hpp"

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>

#include <cmath>
#include <sstream>

#include "cyclone/core/Log.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/mesh/ExodusIO.hpp"
#include "cyclone/solvers/LinearSolver.hpp"

namespace cyclone::cyclic {

PrestressState solveLinearPrestress(const mesh::Mesh& mesh, const fe::DofTransform& transform,
                                    const fe::IsotropicElastic& material, double speedRpm, const fe::Axis& axis,
                                    linalg::CommPtr comm) {
  Timer timer;
  PrestressState state;
  state.speedRpm = speedRpm;
  state.omega = speedRpm * 2 * M_PI / 60;
  state.axis = axis;
  fe::Assembler assembler(mesh, transform, comm);
  auto K = assembler.stiffness(material);
  auto f = assembler.centrifugalLoad(material, state.omega, axis);
  linalg::MultiVector u(assembler.map(), 1);
  solvers::LinearSolveOptions options;
  const auto report = solvers::solveLinear(*K, *f, u, options);
  state.displacement = assembler.nodalField(u);
  // Stresses of every element on every rank: the tangent of any harmonic needs them.
  state.stress.resize(mesh.numElements());
  mesh::Index e = 0;
  for (const auto& block : mesh.blocks) {
    const int n = mesh::nodesPerElement(block.type);
    for (mesh::Index le = 0; le < block.numElements(); ++le, ++e) {
      Eigen::VectorXd ue(3 * n);
      for (int a = 0; a < n; ++a)
        for (int d = 0; d < 3; ++d) ue(3 * a + d) = state.displacement[block.element(le)[a]][d];
      state.stress[e] = fe::elementStresses(block.type, assembler.elementCoords(e), material, ue);
    }
  }
  state.solveSeconds = timer.seconds();
  std::ostringstream msg;
  msg << "linear prestress at " << speedRpm << " rpm: " << transform.numEquations() << " equations, residual "
      << report.relativeResidual << ", " << state.solveSeconds << " s";
  log::info(msg.str());
  return state;
}

void writePrestressExodus(const std::string& path, const mesh::Mesh& mesh, const PrestressState& state) {
  mesh::ExodusResults out;
  out.nodalNames = {"ux", "uy", "uz", "von_mises"};
  out.elementNames = {"s_xx", "s_yy", "s_zz", "s_yz", "s_xz", "s_xy", "von_mises"};
  out.globalNames = {"rpm"};
  mesh::ExodusResults::Step step;
  step.time = state.speedRpm;
  step.global = {state.speedRpm};
  step.nodal.assign(4, std::vector<double>(mesh.numNodes(), 0.0));
  step.element.assign(7, std::vector<double>(mesh.numElements(), 0.0));
  std::vector<Eigen::Matrix<double, 6, 1>> nodalStress(mesh.numNodes(), Eigen::Matrix<double, 6, 1>::Zero());
  std::vector<int> count(mesh.numNodes(), 0);
  mesh::Index e = 0;
  for (const auto& block : mesh.blocks) {
    const int n = mesh::nodesPerElement(block.type);
    for (mesh::Index le = 0; le < block.numElements(); ++le, ++e) {
      const Eigen::Matrix<double, 6, 1> s = state.stress[e].colwise().mean().transpose();
      for (int k = 0; k < 6; ++k) step.element[k][e] = s(k);
      step.element[6][e] = fe::vonMises(s);
      for (int a = 0; a < n; ++a) {
        nodalStress[block.element(le)[a]] += s;
        ++count[block.element(le)[a]];
      }
    }
  }
  for (mesh::Index node = 0; node < mesh.numNodes(); ++node) {
    for (int d = 0; d < 3; ++d) step.nodal[d][node] = state.displacement[node][d];
    if (count[node]) step.nodal[3][node] = fe::vonMises(nodalStress[node] / count[node]);
  }
  out.steps.push_back(std::move(step));
  mesh::writeExodus(path, mesh, out);
}

Teuchos::RCP<linalg::Matrix> tangentStiffness(const fe::Assembler& assembler, const fe::IsotropicElastic& material,
                                              const PrestressState* prestress) {
  if (!prestress || prestress->omega == 0) return assembler.stiffness(material);
  return assembler.assemble([&](mesh::Index e, fe::ElementType type, const fe::ElementCoords& X) {
    Eigen::MatrixXd K = fe::elementStiffness(type, X, material);
    K += fe::elementGeometricStiffness(type, X, prestress->stress[e]);
    K -= fe::elementSpinSoftening(type, X, material.rho, prestress->omega, prestress->axis);
    return K;
  });
}

}  // namespace cyclone::cyclic
