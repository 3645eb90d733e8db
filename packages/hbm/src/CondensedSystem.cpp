#include "cyclone/hbm/CondensedSystem.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <string>

#include "cyclone/core/Error.hpp"

namespace cyclone::hbm {

namespace {

// The rows of T and T_next: one per kept DOF (a unit row), then the columns of each
// element's W and W_next.
void projectionRows(const HarmonicBalanceSystem& full, const std::vector<int>& kept, Eigen::MatrixXd& T,
                    Eigen::MatrixXd& Tnext, std::vector<int>& elementCoordinate) {
  const int n = full.numDofs();
  int rows = int(kept.size());
  for (const auto& c : full.elements()) rows += int(c.W.cols());
  T = Eigen::MatrixXd::Zero(rows, n), Tnext = Eigen::MatrixXd::Zero(rows, n);
  int r = 0;
  for (int dof : kept) T(r++, dof) = 1;
  for (const auto& c : full.elements()) {
    elementCoordinate.push_back(r);
    T.middleRows(r, c.W.cols()) = c.W.transpose();
    if (c.Wnext.size() != 0) Tnext.middleRows(r, c.W.cols()) = c.Wnext.transpose();
    r += int(c.W.cols());
  }
}

// The kept DOFs' coefficients of a load vector of the full system (InputError where it
// acts elsewhere).
Eigen::VectorXd keptLoad(const Eigen::VectorXd& F, int n, int nc, const std::vector<int>& kept, int rows,
                         const char* what) {
  Eigen::VectorXd out = Eigen::VectorXd::Zero(rows * nc);
  for (int dof = 0; dof < n; ++dof) {
    const auto segment = F.segment(dof * nc, nc);
    const auto it = std::find(kept.begin(), kept.end(), dof);
    if (it != kept.end()) out.segment(int(it - kept.begin()) * nc, nc) = segment;
    else if (segment.squaredNorm() > 0)
      throw InputError("condensation", std::string("the ") + what + " acts on DOF " + std::to_string(dof) +
                                           ", which is not kept: keep it");
  }
  return out;
}

}  // namespace

CondensedSystem condenseOntoElements(const HarmonicBalanceSystem& full, const std::vector<int>& keptDofs) {
  if (!full.isReceptance()) throw InputError("condensation", "needs the receptance form");
  const int n = full.numDofs(), nc = full.numCoefficients();
  CondensedSystem out;
  for (int dof : keptDofs) {
    if (dof < 0 || dof >= n)
      throw InputError("condensation", "kept DOF " + std::to_string(dof) + " is not one of the " + std::to_string(n));
    if (std::find(out.keptDofs.begin(), out.keptDofs.end(), dof) == out.keptDofs.end()) out.keptDofs.push_back(dof);
  }
  Eigen::MatrixXd T, Tnext;
  projectionRows(full, out.keptDofs, T, Tnext, out.elementCoordinate);
  const int rows = int(T.rows());
  out.receptance = std::make_shared<ProjectedReceptance>(full.receptance(), T, Tnext);
  // Independent coordinates at every harmonic's phase, or the projected compliance is singular.
  const auto& H = full.aft().harmonics();
  for (int h : H.harmonics()) {
    const Eigen::MatrixXcd Tp = out.receptance->transform(full.phaseIndex(h));
    if (Eigen::FullPivLU<Eigen::MatrixXcd>(Tp).rank() < rows)
      throw InputError("condensation", "the elements' coordinates and the kept DOFs (" + std::to_string(rows) +
                                           ") are not independent at harmonic " + std::to_string(h) +
                                           ": solve the full system");
  }
  out.system = std::make_unique<HarmonicBalanceSystem>(out.receptance, H, full.aft().numSamples());
  if (full.isCyclic()) {
    CyclicCoupling coupling;
    coupling.sectors = full.cyclic().sectors, coupling.engineOrder = full.cyclic().engineOrder;
    out.system->setCyclic(coupling);
  }
  for (std::size_t e = 0; e < full.elements().size(); ++e) {
    const auto& c = full.elements()[e];
    Eigen::MatrixXd W = Eigen::MatrixXd::Zero(rows, c.W.cols());
    W.middleRows(out.elementCoordinate[e], c.W.cols()).setIdentity();
    out.system->addElement(c.element, W);
  }
  out.system->addExcitationCoefficients(keptLoad(full.excitation(), n, nc, out.keptDofs, rows, "excitation"));
  out.system->addStaticLoadCoefficients(keptLoad(full.staticLoad(), n, nc, out.keptDofs, rows, "static load"));
  if (full.usesDynamicStiffness()) out.system->useDynamicStiffness(true);
  return out;
}

Eigen::VectorXd expandToAllDofs(const HarmonicBalanceSystem& full, const CondensedSystem& condensed,
                                const Eigen::VectorXd& Q, double omega, double excitationScale) {
  const HarmonicBalanceSystem& c = *condensed.system;
  Eigen::VectorXd Fnl;
  c.nonlinearForces(Q, omega, Fnl, nullptr);
  const Eigen::VectorXd f = excitationScale * c.excitation() + c.staticLoad() - Fnl;
  // The forces on x: T^T f + T_next^T S^T f per coordinate (S the next-sector map; the
  // element joining sector N-1 to this one pushes back through T_next).
  const int n = full.numDofs(), nc = full.numCoefficients(), rows = c.numDofs();
  Eigen::MatrixXd T = Eigen::MatrixXd::Zero(rows, n), Tn = Eigen::MatrixXd::Zero(rows, n);
  std::vector<int> ignored;
  projectionRows(full, condensed.keptDofs, T, Tn, ignored);
  const Eigen::MatrixXd ST = full.nextSectorMap().transpose();
  Eigen::VectorXd F = Eigen::VectorXd::Zero(n * nc);
  for (int i = 0; i < rows; ++i) {
    const Eigen::VectorXd fi = f.segment(i * nc, nc), back = ST * fi;
    for (int j = 0; j < n; ++j) {
      if (T(i, j) != 0) F.segment(j * nc, nc) += T(i, j) * fi;
      if (Tn(i, j) != 0) F.segment(j * nc, nc) += Tn(i, j) * back;
    }
  }
  return full.complianceOperator(omega) * F;
}

}  // namespace cyclone::hbm
