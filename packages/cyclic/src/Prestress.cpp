#include "cyclone/cyclic/Prestress.hpp"

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>

#include <cmath>
#include <sstream>

#include "cyclone/core/Log.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/mesh/ExodusIO.hpp"
#include "cyclone/core/Error.hpp"
#include "cyclone/solvers/DirectSolver.hpp"
#include "cyclone/solvers/LinearSolver.hpp"
#include "cyclone/solvers/NewtonSolver.hpp"

namespace cyclone::cyclic {

PrestressState solveLinearPrestress(const mesh::Mesh& mesh, const fe::DofTransform& transform,
                                    const fe::IsotropicElastic& material, double speedRpm, const mesh::RotationAxis& axis,
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

namespace {

// The element's displacements gathered from a nodal field.
Eigen::VectorXd elementDisplacement(const mesh::Mesh& mesh, mesh::Index e,
                                    const std::vector<std::array<double, 3>>& field) {
  auto [b, le] = mesh.locateElement(e);
  const auto& block = mesh.blocks[b];
  const int n = mesh::nodesPerElement(block.type);
  Eigen::VectorXd ue(3 * n);
  for (int a = 0; a < n; ++a)
    for (int d = 0; d < 3; ++d) ue(3 * a + d) = field[block.element(le)[a]][d];
  return ue;
}

}  // namespace

PrestressState solveNonlinearPrestress(const mesh::Mesh& mesh, const fe::DofTransform& transform,
                                       const fe::IsotropicElastic& material, double speedRpm, const mesh::RotationAxis& axis,
                                       linalg::CommPtr comm, const NonlinearPrestressOptions& opt) {
  Timer timer;
  PrestressState state;
  state.speedRpm = speedRpm;
  state.omega = speedRpm * 2 * M_PI / 60;
  state.axis = axis;
  state.nonlinear = true;
  fe::Assembler A(mesh, transform, comm);
  // The load on the deformed position is affine in u: f(u) = f1 + K1 u at full speed, scaled by lambda.
  const auto f1 = A.centrifugalLoad(material, state.omega, axis);
  const auto K1 = A.assemble([&](mesh::Index, fe::ElementType t, const fe::ElementCoords& X) {
    return fe::elementSpinSoftening(t, X, material.rho, state.omega, axis);
  });
  const double loadNorm = f1->getVector(0)->norm2();
  auto residual = [&](const linalg::MultiVector& u, double lambda, linalg::MultiVector& R) -> void {
    const auto field = A.nodalField(u);
    auto fint = A.assembleVector([&](mesh::Index e, fe::ElementType t, const fe::ElementCoords& X) {
      return fe::elementTotalLagrangian(t, X, material, elementDisplacement(mesh, e, field), false).internalForce;
    });
    K1->apply(u, R);                      // K1 u
    R.update(1.0, *f1, 1.0);              // f1 + K1 u
    R.update(1.0, *fint, -lambda);        // fint - lambda (f1 + K1 u)
  };

  linalg::MultiVector u(A.map(), 1), trial(A.map(), 1);
  Teuchos::RCP<linalg::Matrix> K0;
  std::shared_ptr<const solvers::DirectSolver> K0factor;
  double lambda = 0, step = std::min(1.0, opt.initialLoadStep);
  bool broyden = true;
  while (lambda < 1.0) {
    const double target = std::min(1.0, lambda + step);
    // Predictor: at u = 0 the tangent has the full spin softening but no stress
    // stiffening yet, so Newton from zero overshoots; start instead from the linear
    // solution (stiffening and softening then balance from the first iteration),
    // and later steps from the load-proportional extrapolation of the last state.
    if (lambda == 0) {
      if (!K0) {
        K0 = A.stiffness(material);
        K0factor = std::make_shared<const solvers::DirectSolver>(*K0);
      }
      linalg::MultiVector load(A.map(), 1);
      load.update(target, *f1, 0.0);
      K0factor->solve(load, trial);
    } else {
      trial.assign(u);
      trial.scale(target / lambda);
    }
    // Newton through NOX on R(u) = f_int(u) - target (f1 + K1 u), Jacobian K_T(u) - target K1.
    // First by Broyden updates of K0's factor (the predictor's): where the stress
    // stiffening and spin softening K0 lacks are small (a disc: 6 iterations, no tangent
    // factored, against 2 Newton iterations with 2 factorizations) the whole prestress
    // costs one factorization. When they stall (a cantilever sector, whose free blades
    // soften strongly), this and every later step is solved by Newton.
    solvers::NewtonProblem problem;
    if (broyden && K0factor) {
      problem.approximateJacobian = K0;
      problem.approximateFactor = K0factor;
    }
    problem.residual = [&](const linalg::MultiVector& x, linalg::MultiVector& Rx) { residual(x, target, Rx); };
    problem.jacobian = [&](const linalg::MultiVector& x) {
      const auto field = A.nodalField(x);
      return A.assemble([&](mesh::Index e, fe::ElementType t, const fe::ElementCoords& X) {
        Eigen::MatrixXd Ke = fe::elementTotalLagrangian(t, X, material, elementDisplacement(mesh, e, field), true).tangent;
        Ke -= target * fe::elementSpinSoftening(t, X, material.rho, state.omega, axis);
        return Ke;
      });
    };
    solvers::NewtonOptions newton;
    newton.absoluteTolerance = opt.tolerance * target * loadNorm;
    newton.maxIterations = opt.maxNewtonIterations;
    const auto report = solvers::solveNewton(problem, trial, newton);
    const bool converged = report.converged;
    const int iterations = report.iterations;
    if (!converged && problem.approximateFactor) {
      state.newtonIterations += iterations;
      broyden = false;  // the same step again, by Newton
      continue;
    }
    state.newtonIterations += iterations;
    state.tangentFactorizations += report.jacobians;
    if (converged) {
      u.assign(trial);
      lambda = target;
      ++state.loadSteps;
      step = std::min(2 * step, 1.0);
      std::ostringstream msg;
      msg << "nonlinear prestress: " << speedRpm * std::sqrt(lambda) << " rpm reached (" << iterations
          << " iterations, " << report.jacobians << " tangents factored)";
      log::info(msg.str());
    } else {
      step *= 0.5;
      if (step < opt.minLoadStep) {
        std::ostringstream msg;
        msg << "nonlinear prestress: " << speedRpm << " rpm cannot be reached; Newton failed even with load step "
            << step * 2 << " of Omega^2; the last converged state is at " << speedRpm * std::sqrt(lambda) << " rpm";
        throw SolverError(msg.str());
      }
    }
  }
  state.displacement = A.nodalField(u);
  state.stress.resize(mesh.numElements());
  for (mesh::Index e = 0; e < mesh.numElements(); ++e) {
    auto [b, le] = mesh.locateElement(e);
    state.stress[e] = fe::elementTotalLagrangian(mesh.blocks[b].type, A.elementCoords(e), material,
                                                 elementDisplacement(mesh, e, state.displacement), false)
                          .cauchy;
  }
  state.solveSeconds = timer.seconds();
  std::ostringstream msg;
  msg << "nonlinear prestress at " << speedRpm << " rpm: " << state.loadSteps << " load steps, "
      << state.newtonIterations << " iterations (" << (broyden ? "Broyden from the linear stiffness, " : "")
      << state.tangentFactorizations << " tangents factored), " << state.solveSeconds << " s";
  log::info(msg.str());
  return state;
}

Eigen::MatrixXd tangentElementMatrix(const mesh::Mesh& mesh, mesh::Index e, fe::ElementType type,
                                     const fe::ElementCoords& X, const fe::IsotropicElastic& material,
                                     const PrestressState* prestress) {
  if (!prestress || prestress->omega == 0) return fe::elementStiffness(type, X, material);
  Eigen::MatrixXd K =
      prestress->nonlinear
          ? fe::elementTotalLagrangian(type, X, material, elementDisplacement(mesh, e, prestress->displacement), true)
                .tangent
          : Eigen::MatrixXd(fe::elementStiffness(type, X, material) +
                            fe::elementGeometricStiffness(type, X, prestress->stress[e]));
  K -= fe::elementSpinSoftening(type, X, material.rho, prestress->omega, prestress->axis);
  return K;
}

Teuchos::RCP<linalg::Matrix> tangentStiffness(const fe::Assembler& assembler, const fe::IsotropicElastic& material,
                                              const PrestressState* prestress) {
  return assembler.assemble([&](mesh::Index e, fe::ElementType type, const fe::ElementCoords& X) {
    return tangentElementMatrix(assembler.mesh(), e, type, X, material, prestress);
  });
}

}  // namespace cyclone::cyclic
