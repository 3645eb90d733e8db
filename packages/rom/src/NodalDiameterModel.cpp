#include "cyclone/rom/NodalDiameterModel.hpp"

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "cyclone/core/Error.hpp"
#include "cyclone/core/Log.hpp"
#include "cyclone/core/NumberText.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/cyclic/CyclicModalAnalysis.hpp"
#include "cyclone/cyclic/CyclicTransform.hpp"
#include "cyclone/solvers/DirectSolver.hpp"
#include "TransposeProduct.hpp"

namespace cyclone::rom {

struct NodalDiameterModel::Impl {
  cyclic::NodalDiameterOperators op;
  RetainedDofSet dofs;
  double eta = 0;
  // Complex solves on the forward travelling wave (half the size) when the real form pairs.
  solvers::ComplexDirectSolver::Structure structure = solvers::ComplexDirectSolver::Structure::General;
  // The unit loads at the retained DOFs, one column per DOF, by their few nonzeros (the
  // equations of a node's directions): formed as right-hand sides a block of columns at a
  // time. Held dense they took the unknowns times the retained DOFs (4.9 GB at 320k
  // unknowns and 1929 DOFs), and every solve with all of them as much again per copy.
  std::vector<std::vector<std::pair<long long, double>>> unitLoads;
  Teuchos::RCP<const linalg::Map> map;
  Teuchos::RCP<linalg::MultiVector> F;  // the load patterns (null: none)

  Eigen::Index size() const { return dofs.size() * op.copies; }

  // Columns first .. first + count - 1 of the unit loads.
  linalg::MultiVector loads(Eigen::Index first, Eigen::Index count) const {
    linalg::MultiVector B(map, std::size_t(count));
    for (Eigen::Index j = 0; j < count; ++j)
      for (const auto& [equation, value] : unitLoads[std::size_t(first + j)])
        B.sumIntoGlobalValue(equation, std::size_t(j), value);
    return B;
  }
  // rhs(:, column) += a * unit load k.
  void addLoad(linalg::MultiVector& rhs, std::size_t column, Eigen::Index k, double a) const {
    for (const auto& [equation, value] : unitLoads[std::size_t(k)]) rhs.sumIntoGlobalValue(equation, column, a * value);
  }
  // G^T solve(G) over columns first .. first + count - 1 of G, a block of columns at a time
  // (`solve(B, X)` fills X for the loads B): the memory of kBlock columns, not all.
  static constexpr Eigen::Index kBlock = 128;
  //
  // In a travelling-wave pair the real form's matrix [[P, -Q], [Q, P]] commutes with the
  // pair's rotation J (x_a, x_b) -> (-x_b, x_a): where copy 1's unit loads are copy 0's
  // rotated (copyOneRotation = +-1), their responses are copy 0's rotated, and only copy
  // 0's columns are solved (half the static correction's solves on a two-copy nodal
  // diameter: most of its model's time at the seed's mesh size).
  int copyOneRotation = 0;
  template <class Solve>
  Eigen::MatrixXd retainedResponse(Eigen::Index count, const Solve& solve) const {
    Eigen::MatrixXd out(size(), count);
    const Eigen::Index nd = dofs.size();
    const bool rotate = copyOneRotation != 0 && count == size() && op.copies == 2;
    for (Eigen::Index first = 0; first < (rotate ? nd : count); first += kBlock) {
      const Eigen::Index n = std::min(kBlock, (rotate ? nd : count) - first);
      const linalg::MultiVector B = loads(first, n);
      linalg::MultiVector X(map, std::size_t(n));
      solve(B, X);
      out.middleCols(first, n) = retained(X);
      if (!rotate) continue;
      rotatePairs(X, copyOneRotation);
      out.middleCols(nd + first, n) = retained(X);
    }
    return out;
  }
  // X <- s J X, J (x_a, x_b) -> (-x_b, x_a) on every pair (2m, 2m + 1) of equations (one
  // process: both of a pair are local).
  static void rotatePairs(linalg::MultiVector& X, int s) {
    for (std::size_t j = 0; j < X.getNumVectors(); ++j) {
      auto x = X.getDataNonConst(j);
      for (decltype(x.size()) i = 0; i + 1 < x.size(); i += 2) {
        const double a = x[i], b = x[i + 1];
        x[i] = -s * b, x[i + 1] = s * a;
      }
    }
  }
  // +1 or -1 where every copy-1 unit load is +-J of the same DOF's copy-0 one, on one
  // process whose equations pair from 0; 0 otherwise (every column is then solved).
  int findCopyOneRotation() const {
    if (op.copies != 2 || map->getComm()->getSize() != 1 || map->getMinAllGlobalIndex() != 0 || !map->isContiguous() ||
        map->getGlobalNumElements() % 2 != 0)
      return 0;
    const std::size_t nd = std::size_t(dofs.size());
    for (int s : {1, -1}) {
      bool all = true;
      for (std::size_t k = 0; k < nd && all; ++k) {
        std::map<long long, double> rotated, given;
        for (const auto& [equation, value] : unitLoads[k]) {
          const bool first = equation % 2 == 0;
          rotated[first ? equation + 1 : equation - 1] += first ? s * value : -s * value;
        }
        for (const auto& [equation, value] : unitLoads[nd + k]) given[equation] += value;
        if (rotated.size() != given.size()) all = false;
        for (auto a = rotated.begin(), b = given.begin(); all && a != rotated.end(); ++a, ++b)
          all = a->first == b->first && std::abs(a->second - b->second) <= 1e-14 * std::abs(a->second);
      }
      if (all) return s;
    }
    return 0;
  }

  // G^T X: every column of X seen at the retained DOFs (along each DOF's unit vector).
  Eigen::MatrixXd retained(const linalg::MultiVector& X) const {
    const auto nd = dofs.size();
    Eigen::MatrixXd out(size(), X.getNumVectors());
    for (std::size_t j = 0; j < X.getNumVectors(); ++j)
      for (int c = 0; c < op.copies; ++c) {
        const auto field = op.assembler->nodalField(X, int(j), c);
        for (Eigen::Index k = 0; k < nd; ++k) {
          double sum = 0;
          const Eigen::Vector3d axis = dofs.axis(k);
          dofs.forEachNode(k, [&](mesh::Index node, double w) {
            const auto& u = field[std::size_t(node)];
            sum += w * axis.dot(Eigen::Vector3d(u[0], u[1], u[2]));
          });
          out(c * nd + k, Eigen::Index(j)) = sum;
        }
      }
    return out;
  }
};

NodalDiameterModel::NodalDiameterModel(const mesh::Mesh& mesh, const cyclic::CyclicSector& sector,
                                         const NodalDiameterModelProblem& problem, linalg::CommPtr comm)
    : impl_(std::make_unique<Impl>()) {
  auto& I = *impl_;
  problem.material.validate("material");
  if (!(problem.lossFactor >= 0)) throw InputError("loss_factor", "must be >= 0");
  I.dofs = rom::retainedDofs(mesh, problem.retainedNodeSets, problem.retainedDirections, problem.retainedMeans);
  Timer timer;
  I.op = cyclic::assembleNodalDiameterOperators(mesh, sector, problem.nodalDiameter, problem.material, problem.fixedNodeSets,
                                           problem.prestress.get(), comm);
  I.eta = problem.lossFactor;
  if (cyclic::travellingWavePaired(I.op.assembler->transform()))
    I.structure = solvers::ComplexDirectSolver::Structure::TravellingWavePairs;

  const auto& T = I.op.assembler->transform();
  const auto map = I.op.assembler->map();
  I.map = map;
  I.unitLoads.assign(std::size_t(I.size()), {});
  const auto nd = I.dofs.size();
  for (int c = 0; c < I.op.copies; ++c)
    for (Eigen::Index k = 0; k < nd; ++k) {
      const Eigen::Vector3d axis = I.dofs.axis(k);
      auto& load = I.unitLoads[std::size_t(c * nd + k)];
      I.dofs.forEachNode(k, [&](mesh::Index node, double w) {
        for (int d = 0; d < 3; ++d)
          for (const auto& term : T.terms(node, d, c))
            if (axis[d] != 0 && map->isNodeGlobalElement(term.equation))
              load.emplace_back(term.equation, w * axis[d] * term.coefficient);
      });
    }
  if (I.structure == solvers::ComplexDirectSolver::Structure::TravellingWavePairs) I.copyOneRotation = I.findCopyOneRotation();
  if (!problem.loads.empty()) {
    I.F = Teuchos::rcp(new linalg::MultiVector(map, problem.loads.size()));
    for (std::size_t p = 0; p < problem.loads.size(); ++p) {
      const auto& load = problem.loads[p];
      const std::string where = "loads/" + (load.name.empty() ? std::to_string(p) : load.name);
      if (load.forces.empty()) throw InputError(where, "no forces given");
      for (const auto& f : load.forces) {
        if (f.node < 0 || f.node >= mesh.numNodes())
          throw InputError(where, "node index " + std::to_string(f.node) + " is not in the mesh");
        if (f.copy < 0 || f.copy >= I.op.copies)
          throw InputError(where, "copy " + std::to_string(f.copy) + " at nodal diameter " +
                                      std::to_string(problem.nodalDiameter) + " (it has " + std::to_string(I.op.copies) +
                                      " real-form copies)");
        if (!f.force.allFinite()) throw InputError(where, "a force that is not a finite number");
        for (int d = 0; d < 3; ++d)
          for (const auto& term : T.terms(f.node, d, f.copy))  // a fixed DOF takes no load
            if (f.force[d] != 0 && map->isNodeGlobalElement(term.equation))
              I.F->sumIntoGlobalValue(term.equation, p, f.force[d] * term.coefficient);
      }
    }
  }
  std::ostringstream msg;
  msg << "nodal diameter model k = " << problem.nodalDiameter << ": " << T.numEquations() << " equations, " << I.size()
      << " retained DOFs (" << nd << " per copy on " << I.dofs.nodes.size() << " nodes";
  if (!I.dofs.means.empty()) msg << " and " << I.dofs.means.size() << " means";
  msg << ", " << I.op.copies << " copies), assembled in " << timer.seconds() << " s";
  log::info(msg.str());
}

NodalDiameterModel::~NodalDiameterModel() = default;

int NodalDiameterModel::nodalDiameter() const { return impl_->op.nodalDiameter; }
int NodalDiameterModel::copies() const { return impl_->op.copies; }
long long NodalDiameterModel::equations() const { return impl_->op.assembler->transform().numEquations(); }
double NodalDiameterModel::lossFactor() const { return impl_->eta; }
const std::vector<mesh::Index>& NodalDiameterModel::retainedNodes() const { return impl_->dofs.nodes; }
const RetainedDofSet& NodalDiameterModel::retainedDofs() const { return impl_->dofs; }
Eigen::Index NodalDiameterModel::size() const { return impl_->size(); }
const cyclic::NodalDiameterOperators& NodalDiameterModel::operators() const { return impl_->op; }
linalg::MultiVector NodalDiameterModel::retainedLoads(Eigen::Index first, Eigen::Index count) const {
  if (first < 0 || count < 0 || first + count > size())
    throw InputError("retained loads", "columns " + std::to_string(first) + " .. " + std::to_string(first + count - 1) +
                                           " of " + std::to_string(size()));
  return impl_->loads(first, count);
}

Eigen::MatrixXcd NodalDiameterModel::compliance(double omega) const {
  const auto& I = *impl_;
  const solvers::ComplexDirectSolver solver(*I.op.K, {1.0, I.eta}, *I.op.M, -omega * omega, I.structure);
  // Only copy a's loads are solved for. Copy b's are i times them, and i commutes with
  // K_k and M_k, so their responses are i times (copy a's reading -b, copy b's reading a).
  const auto nd = I.dofs.size();
  Eigen::MatrixXcd A(I.size(), I.size());
  for (Eigen::Index first = 0; first < nd; first += Impl::kBlock) {  // a block of copy a's loads at a time
    const Eigen::Index n = std::min(Impl::kBlock, nd - first);
    const linalg::MultiVector B = I.loads(first, n);
    linalg::MultiVector xr(I.map, std::size_t(n)), xi(I.map, std::size_t(n));
    solver.solve(B, xr, xi);
    A.middleCols(first, n).real() = I.retained(xr);
    A.middleCols(first, n).imag() = I.retained(xi);
  }
  if (I.op.copies == 2) {
    A.block(0, nd, nd, nd) = -A.block(nd, 0, nd, nd);
    A.block(nd, nd, nd, nd) = A.block(0, 0, nd, nd);
  }
  return A;
}

Eigen::MatrixXcd NodalDiameterModel::complianceTimes(double omega, const Eigen::MatrixXd& X) const {
  const auto& I = *impl_;
  const auto nd = I.dofs.size();
  if (X.rows() != I.size())
    throw InputError("compliance times", std::to_string(X.rows()) + " rows; the model has " +
                                             std::to_string(I.size()) + " retained DOFs");
  // A = [L_a, -L_b; L_b, L_a] with [L_a; L_b] copy a's loads' responses (compliance()):
  // A X = L X_a + [-L_b X_b; L_a X_b], L Y the responses to the loads G_a Y.
  const auto p = X.cols();
  const int copies = I.op.copies;
  linalg::MultiVector rhs(I.map, std::size_t(copies * p));
  for (int c = 0; c < copies; ++c)
    for (Eigen::Index j = 0; j < p; ++j)
      for (Eigen::Index k = 0; k < nd; ++k)
        if (const double a = X(c * nd + k, j); a != 0) I.addLoad(rhs, std::size_t(c * p + j), k, a);
  const solvers::ComplexDirectSolver solver(*I.op.K, {1.0, I.eta}, *I.op.M, -omega * omega, I.structure);
  linalg::MultiVector xr(I.map, std::size_t(copies * p)), xi(I.map, std::size_t(copies * p));
  solver.solve(rhs, xr, xi);
  Eigen::MatrixXcd LY(I.size(), copies * p);
  LY.real() = I.retained(xr);
  LY.imag() = I.retained(xi);
  Eigen::MatrixXcd AX = LY.leftCols(p);
  if (copies == 2) {
    AX.topRows(nd) -= LY.rightCols(p).bottomRows(nd);
    AX.bottomRows(nd) += LY.rightCols(p).topRows(nd);
  }
  return AX;
}

std::vector<Eigen::Vector3cd> NodalDiameterModel::fieldResponse(double omega, const Eigen::VectorXcd& forces,
                                                                 int sign) const {
  const auto& I = *impl_;
  const auto nd = I.dofs.size();
  if (forces.size() != nd)
    throw InputError("field response", "forces on " + std::to_string(forces.size()) + " DOFs; the model retains " +
                                           std::to_string(nd) + " per copy");
  if (sign != 1 && sign != -1) throw InputError("field response", "the travelling wave's sign must be +1 or -1");
  // Columns: the real and the imaginary part of the load, each on copy a's retained DOFs.
  linalg::MultiVector rhs(I.map, 2);
  for (Eigen::Index k = 0; k < nd; ++k) {
    if (forces(k).real() != 0) I.addLoad(rhs, 0, k, forces(k).real());
    if (forces(k).imag() != 0) I.addLoad(rhs, 1, k, forces(k).imag());
  }
  const double eta = omega == 0 ? 0.0 : I.eta;
  const solvers::ComplexDirectSolver solver(*I.op.K, {1.0, eta}, *I.op.M, -omega * omega, I.structure);
  linalg::MultiVector xr(I.map, 2), xi(I.map, 2);
  solver.solve(rhs, xr, xi);
  const auto& mesh = I.op.assembler->mesh();
  std::vector<Eigen::Vector3cd> u(std::size_t(mesh.numNodes()), Eigen::Vector3cd::Zero());
  const std::complex<double> i(0, 1);
  for (int c = 0; c < I.op.copies; ++c) {
    // The copy's complex field: x(f_r) + i x(f_i), each solve giving xr + i xi.
    const auto r0 = I.op.assembler->nodalField(xr, 0, c), i0 = I.op.assembler->nodalField(xi, 0, c);
    const auto r1 = I.op.assembler->nodalField(xr, 1, c), i1 = I.op.assembler->nodalField(xi, 1, c);
    const std::complex<double> weight = c == 0 ? std::complex<double>(1.0) : double(sign) * i;
    for (std::size_t n = 0; n < u.size(); ++n)
      for (int d = 0; d < 3; ++d)
        u[n](d) += weight * std::complex<double>(r0[n][d] - i1[n][d], i0[n][d] + r1[n][d]);
  }
  return u;
}

Eigen::Index NodalDiameterModel::numLoads() const {
  return impl_->F.is_null() ? 0 : Eigen::Index(impl_->F->getNumVectors());
}

Eigen::MatrixXcd NodalDiameterModel::loadResponse(double omega) const {
  const auto& I = *impl_;
  if (I.F.is_null()) return ComplianceModel::loadResponse(omega);  // the InputError
  const solvers::ComplexDirectSolver solver(*I.op.K, {1.0, I.eta}, *I.op.M, -omega * omega, I.structure);
  linalg::MultiVector xr(I.F->getMap(), I.F->getNumVectors()), xi(I.F->getMap(), I.F->getNumVectors());
  solver.solve(*I.F, xr, xi);
  Eigen::MatrixXcd X(I.size(), numLoads());
  X.real() = I.retained(xr);
  X.imag() = I.retained(xi);
  return X;
}

Eigen::MatrixXd NodalDiameterModel::zeroFrequencyCompliance() const {
  const auto& I = *impl_;
  std::unique_ptr<solvers::DirectSolver> solver;
  try {
    solver = std::make_unique<solvers::DirectSolver>(*I.op.K, I.op.M.get(), 0.0);
  } catch (const std::exception& e) {
    throw InputError("reduced model", std::string("K does not factor at zero frequency (a free sector has no static "
                                                  "compliance): ") + e.what());
  }
  const Eigen::MatrixXd A =
      I.retainedResponse(I.size(), [&](const linalg::MultiVector& B, linalg::MultiVector& X) { solver->solve(B, X); });
  return 0.5 * (A + A.transpose());
}

RetainedModes NodalDiameterModel::modes(int distinct, double shift) const {
  const auto& I = *impl_;
  if (distinct < 1) throw InputError("modes", "must be at least 1");
  Timer timer;
  const auto result = cyclic::solveNodalDiameterModes(I.op, distinct, shift);
  RetainedModes out;
  out.copies = I.op.copies;
  out.eigenvalues = result.eigenvalues;
  // A two-copy nodal diameter's modes come in travelling-wave pairs of one eigenvalue;
  // the solver's two Ritz values of a pair differ by its accuracy (up to 3e-10 of it on
  // the built-in sector), and the realization of the pair as one travelling wave
  // (SectorReceptance) takes their mean: both take it, so the model's compliance and its
  // modal realization are one model.
  if (out.copies == 2)
    for (std::size_t j = 0; j + 1 < out.eigenvalues.size(); ++j) {
      const double a = out.eigenvalues[j], b = out.eigenvalues[j + 1];
      const bool alone = (j == 0 || std::abs(a - out.eigenvalues[j - 1]) > 1e-8 * std::abs(a)) &&
                         (j + 2 >= out.eigenvalues.size() || std::abs(out.eigenvalues[j + 2] - b) > 1e-8 * std::abs(b));
      if (alone && std::abs(b - a) <= 1e-8 * std::abs(a)) out.eigenvalues[j] = out.eigenvalues[j + 1] = 0.5 * (a + b), ++j;
    }
  out.shapes = I.retained(*result.modes);
  if (!I.F.is_null()) out.loads = transposeProduct(*result.modes, *I.F);
  out.seconds = timer.seconds();
  return out;
}

StaticCompliance NodalDiameterModel::staticCompliance(double omega0, const RetainedModes& modes) const {
  const auto& I = *impl_;
  if (modes.shapes.rows() != I.size() || modes.numModes() == 0)
    throw InputError("modes", "not computed with this model (" + std::to_string(modes.shapes.rows()) +
                                  " retained DOFs, the model has " + std::to_string(I.size()) + ")");
  if (!(omega0 >= 0)) throw InputError("omega0", "must be >= 0");
  Timer timer;
  StaticCompliance out;
  out.omega0 = omega0;
  out.shift = omega0 * omega0;
  const int rigid = modes.numRigidBodyModes();
  const auto hz = [](double lambda) { return std::sqrt(std::max(lambda, 0.0)) / (2 * M_PI); };
  std::ostringstream note;
  if (omega0 == 0 && rigid > 0) {
    if (rigid == modes.numModes())
      throw InputError("omega0", "0 with only rigid-body modes computed: compute elastic modes too");
    out.shift = 0.5 * modes.eigenvalues[rigid];
    note << "omega0 = 0 with " << rigid << " rigid-body mode(s): K is singular; shifted to sigma = "
         << out.shift << " (rad/s)^2 (omega0 = " << std::sqrt(out.shift) << " rad/s, " << hz(out.shift)
         << " Hz), half the first elastic eigenvalue";
    log::info("static compliance: " + note.str());
  } else {
    if (out.shift >= modes.eigenvalues.back())
      throw InputError("omega0", numberText(omega0) + " rad/s is not below the highest computed natural "
                                 "frequency (" + numberText(hz(modes.eigenvalues.back())) +
                                 " Hz): compute more modes or lower omega0");
    for (int j = 0; j < modes.numModes(); ++j) {
      const double l = modes.eigenvalues[j];
      if (std::abs(l - out.shift) <= 1e-3 * std::abs(l))
        throw InputError("omega0", numberText(omega0) + " rad/s (" + numberText(hz(out.shift)) +
                                       " Hz) is on natural frequency " + std::to_string(j / modes.copies + 1) + " (" +
                                       numberText(hz(l)) + " Hz): K - omega0^2 M is singular there; "
                                       "choose omega0 away from the natural frequencies (0 for a held sector)");
    }
    note << "sigma = omega0^2 = " << out.shift << " (rad/s)^2";
  }
  const bool definite = out.shift < modes.eigenvalues.front();
  const bool paired = I.structure == solvers::ComplexDirectSolver::Structure::TravellingWavePairs;
  const solvers::DirectSolver solver(*I.op.K, I.op.M.get(), out.shift,
                                     definite ? solvers::DirectSolver::Definiteness::Positive
                                              : solvers::DirectSolver::Definiteness::Indefinite,
                                     paired ? solvers::DirectSolver::Structure::TravellingWavePairs
                                            : solvers::DirectSolver::Structure::General);
  out.matrix =
      I.retainedResponse(I.size(), [&](const linalg::MultiVector& B, linalg::MultiVector& X) { solver.solve(B, X); });
  out.matrix = 0.5 * (out.matrix + out.matrix.transpose()).eval();
  if (!I.F.is_null()) {
    linalg::MultiVector XF(I.F->getMap(), I.F->getNumVectors());
    solver.solve(*I.F, XF);
    out.loadResponse = I.retained(XF);
  }
  out.note = note.str();
  out.seconds = timer.seconds();
  return out;
}

}  // namespace cyclone::rom
