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
fe::ElementVector elementDisplacement(const mesh::Mesh& mesh, mesh::Index e,
                                      const std::vector<std::array<double, 3>>& field) {
  auto [b, le] = mesh.locateElement(e);
  const auto& block = mesh.blocks[b];
  const int n = mesh::nodesPerElement(block.type);
  fe::ElementVector ue(3 * n);
  for (int a = 0; a < n; ++a)
    for (int d = 0; d < 3; ++d) ue(3 * a + d) = field[block.element(le)[a]][d];
  return ue;
}

}  // namespace

namespace {

// The geometrically nonlinear centrifugal state by load steps in Omega^2 (lambda from
// 0 to 1), each solved by Newton through NOX. The load on the deformed position is
// affine in u: f(u) = f1 + K1 u at full speed, scaled by lambda.
class NonlinearPrestressSolver {
public:
  NonlinearPrestressSolver(const mesh::Mesh& mesh, const fe::DofTransform& transform,
                           const fe::IsotropicElastic& material, double speedRpm, const mesh::RotationAxis& axis,
                           linalg::CommPtr comm)
      : mesh_(mesh), material_(material), A_(mesh, transform, comm), speedRpm_(speedRpm),
        omega_(speedRpm * 2 * M_PI / 60), axis_(axis) {
    f1_ = A_.centrifugalLoad(material, omega_, axis);
    K1_ = A_.assemble([&](mesh::Index, fe::ElementType t, const fe::ElementCoords& X) {
      return fe::elementSpinSoftening(t, X, material.rho, omega_, axis, material.massQuadrature);
    });
  }
  PrestressState solve(const NonlinearPrestressOptions& opt);

private:
  // R(u) = f_int(u) - lambda (f1 + K1 u).
  void residual(const linalg::MultiVector& u, double lambda, linalg::MultiVector& R) const {
    const auto field = A_.nodalField(u);
    auto fint = A_.assembleVector([&](mesh::Index e, fe::ElementType t, const fe::ElementCoords& X) {
      return fe::elementTotalLagrangian(t, X, material_, elementDisplacement(mesh_, e, field), false).internalForce;
    });
    K1_->apply(u, R);                // K1 u
    R.update(1.0, *f1_, 1.0);        // f1 + K1 u
    R.update(1.0, *fint, -lambda);   // fint - lambda (f1 + K1 u)
  }
  // Its Jacobian K_T(u) - lambda K1.
  Teuchos::RCP<linalg::Matrix> tangent(const linalg::MultiVector& u, double lambda) const {
    const auto field = A_.nodalField(u);
    return A_.assemble([&](mesh::Index e, fe::ElementType t, const fe::ElementCoords& X) {
      fe::ElementMatrix Ke = fe::elementTotalLagrangian(t, X, material_, elementDisplacement(mesh_, e, field), true).tangent;
      Ke -= lambda * fe::elementSpinSoftening(t, X, material_.rho, omega_, axis_, material_.massQuadrature);
      return Ke;
    });
  }
  // The start of the step to `target`. At u = 0 the tangent has the full spin softening
  // but no stress stiffening yet, so Newton from zero overshoots; start instead from the
  // linear solution (stiffening and softening then balance from the first iteration),
  // and later steps from the load-proportional extrapolation of the last state.
  void predict(double lambda, double target, const linalg::MultiVector& u, linalg::MultiVector& trial) {
    if (lambda > 0) {
      trial.assign(u);
      trial.scale(target / lambda);
      return;
    }
    if (!K0_) {
      K0_ = A_.stiffness(material_);
      K0factor_ = std::make_shared<const solvers::DirectSolver>(*K0_);
    }
    linalg::MultiVector load(A_.map(), 1);
    load.update(target, *f1_, 0.0);
    K0factor_->solve(load, trial);
  }
  // Newton on the step to `target` from trial. With `broyden`, by Broyden updates of
  // K0's factor (the predictor's): where the stress stiffening and spin softening K0
  // lacks are small (a disc: 6 iterations, no tangent factored, against 2 Newton
  // iterations with 2 factorizations) the whole prestress costs one factorization.
  solvers::NewtonReport solveStep(double target, bool broyden, double tolerance, int maxIterations,
                                  linalg::MultiVector& trial) const {
    solvers::NewtonProblem problem;
    if (broyden && K0factor_) {
      problem.approximateJacobian = K0_;
      problem.approximateFactor = K0factor_;
    }
    problem.residual = [&](const linalg::MultiVector& x, linalg::MultiVector& Rx) { residual(x, target, Rx); };
    problem.jacobian = [&](const linalg::MultiVector& x) { return tangent(x, target); };
    solvers::NewtonOptions newton;
    newton.absoluteTolerance = tolerance;
    newton.maxIterations = maxIterations;
    return solvers::solveNewton(problem, trial, newton);
  }
  void finish(const linalg::MultiVector& u, PrestressState& state) const {
    state.displacement = A_.nodalField(u);
    state.stress.resize(mesh_.numElements());
    for (mesh::Index e = 0; e < mesh_.numElements(); ++e) {
      auto [b, le] = mesh_.locateElement(e);
      state.stress[e] = fe::elementTotalLagrangian(mesh_.blocks[b].type, A_.elementCoords(e), material_,
                                                   elementDisplacement(mesh_, e, state.displacement), false)
                            .cauchy;
    }
  }

  const mesh::Mesh& mesh_;
  const fe::IsotropicElastic& material_;
  fe::Assembler A_;
  const double speedRpm_, omega_;
  const mesh::RotationAxis axis_;
  Teuchos::RCP<linalg::MultiVector> f1_;
  Teuchos::RCP<linalg::Matrix> K1_, K0_;
  std::shared_ptr<const solvers::DirectSolver> K0factor_;
};

PrestressState NonlinearPrestressSolver::solve(const NonlinearPrestressOptions& opt) {
  Timer timer;
  PrestressState state;
  state.speedRpm = speedRpm_, state.omega = omega_, state.axis = axis_, state.nonlinear = true;
  const double loadNorm = f1_->getVector(0)->norm2();
  linalg::MultiVector u(A_.map(), 1), trial(A_.map(), 1);
  double lambda = 0, step = std::min(1.0, opt.initialLoadStep);
  bool broyden = true;  // until Broyden stalls (a cantilever sector's free blades soften strongly): then Newton
  while (lambda < 1.0) {
    const double target = std::min(1.0, lambda + step);
    predict(lambda, target, u, trial);
    const bool byBroyden = broyden && K0factor_;
    const auto report = solveStep(target, broyden, opt.tolerance * target * loadNorm, opt.maxNewtonIterations, trial);
    state.newtonIterations += report.iterations;
    if (!report.converged && byBroyden) {
      broyden = false;  // the same step again, by Newton
      continue;
    }
    state.tangentFactorizations += report.jacobians;
    if (report.converged) {
      u.assign(trial);
      lambda = target;
      ++state.loadSteps;
      step = std::min(2 * step, 1.0);
      std::ostringstream msg;
      msg << "nonlinear prestress: " << speedRpm_ * std::sqrt(lambda) << " rpm reached (" << report.iterations
          << " iterations, " << report.jacobians << " tangents factored)";
      log::info(msg.str());
      continue;
    }
    step *= 0.5;
    if (step < opt.minLoadStep) {
      std::ostringstream msg;
      msg << "nonlinear prestress: " << speedRpm_ << " rpm cannot be reached; Newton failed even with load step "
          << step * 2 << " of Omega^2; the last converged state is at " << speedRpm_ * std::sqrt(lambda) << " rpm";
      throw SolverError(msg.str());
    }
  }
  finish(u, state);
  state.solveSeconds = timer.seconds();
  std::ostringstream msg;
  msg << "nonlinear prestress at " << speedRpm_ << " rpm: " << state.loadSteps << " load steps, "
      << state.newtonIterations << " iterations (" << (broyden ? "Broyden from the linear stiffness, " : "")
      << state.tangentFactorizations << " tangents factored), " << state.solveSeconds << " s";
  log::info(msg.str());
  return state;
}

}  // namespace

PrestressState solveNonlinearPrestress(const mesh::Mesh& mesh, const fe::DofTransform& transform,
                                       const fe::IsotropicElastic& material, double speedRpm, const mesh::RotationAxis& axis,
                                       linalg::CommPtr comm, const NonlinearPrestressOptions& opt) {
  return NonlinearPrestressSolver(mesh, transform, material, speedRpm, axis, comm).solve(opt);
}

void modalElementMatrices(const mesh::Mesh& mesh, mesh::Index e, fe::ElementType type, const fe::ElementCoords& X,
                          const fe::IsotropicElastic& material, const PrestressState* prestress, fe::ElementMatrix& K,
                          fe::ElementMatrix* M) {
  fe::ElementPrestress p;
  fe::PointStresses stress;
  fe::ElementVector displacement;
  if (prestress && prestress->omega != 0) {
    p.omega = prestress->omega, p.axis = prestress->axis;
    if (prestress->nonlinear) {
      p.kind = fe::ElementPrestress::Kind::Nonlinear;
      displacement = elementDisplacement(mesh, e, prestress->displacement);
      p.displacement = &displacement;
    } else {
      p.kind = fe::ElementPrestress::Kind::Linear;
      stress = prestress->stress[std::size_t(e)];
      p.stress = &stress;
    }
  }
  fe::elementModalMatrices(type, X, material, p, K, M, material.massQuadrature);
}

fe::ElementMatrix tangentElementMatrix(const mesh::Mesh& mesh, mesh::Index e, fe::ElementType type,
                                       const fe::ElementCoords& X, const fe::IsotropicElastic& material,
                                       const PrestressState* prestress) {
  fe::ElementMatrix K;
  modalElementMatrices(mesh, e, type, X, material, prestress, K);
  return K;
}

Teuchos::RCP<linalg::Matrix> tangentStiffness(const fe::Assembler& assembler, const fe::IsotropicElastic& material,
                                              const PrestressState* prestress) {
  return assembler.assemble([&](mesh::Index e, fe::ElementType type, const fe::ElementCoords& X) {
    return tangentElementMatrix(assembler.mesh(), e, type, X, material, prestress);
  });
}

}  // namespace cyclone::cyclic
