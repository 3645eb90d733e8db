#pragma once
// The full FE model of a cyclic sector at one nodal diameter k, seen at
// retained DOFs (the nodes of some node sets, all 3 directions or chosen ones,
// in the global frame or a given local one: RetainedDofs.hpp): the
// real-form K_k (prestressed tangent when given) and M_k assembled as for the
// modes (cyclic::assembleNodalDiameterOperators), and from them
//   - the full-FE dynamic compliance G^T ((1 + i eta) K - w^2 M)^{-1} G by a
//     sparse complex LU per frequency: the reference for every reduced model;
//   - the modes at the retained DOFs (Anasazi shift-invert);
//   - the exact static compliance G^T (K - sigma M)^{-1} G from one CHOLMOD
//     factorization with all retained DOFs as right-hand sides.
// G maps unknowns to the retained physical DOFs (a right-face node is a
// combination of left-face unknowns; a fixed DOF has a zero column); its column
// for a DOF in a local frame is the unit load along that frame vector.
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "cyclone/cyclic/CyclicSector.hpp"
#include "cyclone/cyclic/Prestress.hpp"
#include "cyclone/fe/LinearAlgebra.hpp"
#include "cyclone/fe/Material.hpp"
#include "cyclone/rom/HybridFrfModel.hpp"
#include "cyclone/rom/LoadPattern.hpp"
#include "cyclone/rom/RetainedDofs.hpp"

namespace cyclone::cyclic {
struct NodalDiameterOperators;
}

namespace cyclone::rom {

struct NodalDiameterModelProblem {
  fe::IsotropicElastic material;
  int nodalDiameter = 0;                        ///< k in 0..N/2
  std::vector<std::string> fixedNodeSets;       ///< e.g. {"bore"}; all 3 components held
  std::vector<std::string> retainedNodeSets;    ///< merged in order, duplicates dropped
  std::map<std::string, RetainedDirections> retainedDirections;  ///< by set; a set not here: x, y, z
  std::vector<RetainedMean> retainedMeans;      ///< weighted sums of nodes, retained after the sets' nodes
  std::vector<LoadPattern> loads;               ///< the excitation part: loads that need not act at retained DOFs
  std::shared_ptr<const cyclic::PrestressState> prestress;  ///< tangent K + K_sigma - K_Omega; null: K
  double lossFactor = 0;                        ///< eta of the structural damping (1 + i eta) K
};

class NodalDiameterModel final : public ComplianceModel {
public:
  /// Assembles K_k, M_k. InputError for k outside 0..N/2, missing or empty retained sets.
  NodalDiameterModel(const mesh::Mesh& mesh, const cyclic::CyclicSector& sector, const NodalDiameterModelProblem& problem,
                      linalg::CommPtr comm);
  ~NodalDiameterModel() override;
  NodalDiameterModel(const NodalDiameterModel&) = delete;
  NodalDiameterModel& operator=(const NodalDiameterModel&) = delete;

  int nodalDiameter() const;
  int copies() const;
  long long equations() const;
  double lossFactor() const;
  const std::vector<mesh::Index>& retainedNodes() const;
  /// The retained DOFs of one copy (copy c's DOF k is compliance row c * dofs + k).
  const RetainedDofSet& retainedDofs() const;
  Eigen::Index size() const override;

  /// The full-FE compliance at the retained DOFs (one complex factorization).
  Eigen::MatrixXcd compliance(double omega) const override;
  /// A(omega) X by one complex factorization and a solve per column of X and copy.
  Eigen::MatrixXcd complianceTimes(double omega, const Eigen::MatrixXd& X) const override;
  /// G^T K^{-1} G (CHOLMOD); InputError when K is singular (a free sector).
  Eigen::MatrixXd zeroFrequencyCompliance() const override;
  /// G^T ((1 + i eta) K - w^2 M)^{-1} F for the load patterns F (one complex factorization):
  /// the reference for the reduced models' excitation part.
  Eigen::Index numLoads() const override;
  Eigen::MatrixXcd loadResponse(double omega) const override;

  /// The lowest `distinct` natural frequencies' modes (pairs twice) at the retained
  /// DOFs, with phi_j^T f for the load patterns; shift as in solvers::ModalOptions
  /// (automaticShift() for a free sector).
  RetainedModes modes(int distinct, double shift = 0) const;

  /// The exact compliance at sigma = omega0^2 for the hybrid model, checked against
  /// `modes` (computed with this model): omega0^2 within 1e-3 (relative) of a natural
  /// frequency's square, or at or above the highest computed one, is an InputError.
  /// omega0 = 0 with rigid-body modes among `modes`: sigma moves automatically to half
  /// the first elastic eigenvalue (reported in the note and the log). The load patterns'
  /// static response G^T (K - sigma M)^{-1} F comes from the same factorization.
  StaticCompliance staticCompliance(double omega0, const RetainedModes& modes) const;

  /// The whole sector's displacement (per node, complex) under forces at the retained DOFs of
  /// one copy, for the travelling wave SectorReceptance gives this nodal diameter with `sign`
  /// (SectorReceptance::nodalDiameter): u = u_a + sign i u_b from one complex solve, so that u
  /// at the retained DOFs is (P + sign i Q) f, the receptance the harmonic balance used.
  /// omega = 0: the undamped static solve (harmonic 0's convention). The reference for a
  /// reduced model's expansion, and what stresses are recovered from.
  std::vector<Eigen::Vector3cd> fieldResponse(double omega, const Eigen::VectorXcd& forces, int sign) const;

  /// The real-form K_k, M_k and their unknowns: what reductions onto the retained
  /// DOFs (Guyan, Craig-Bampton: BoundaryReduction) work on.
  const cyclic::NodalDiameterOperators& operators() const;
  /// Columns first .. first + count - 1 of G, the unit loads at the retained DOFs as
  /// right-hand sides on the unknowns, one column per retained DOF (order as in
  /// ComplianceModel). Formed on demand: all of them at once are the unknowns times the
  /// retained DOFs.
  linalg::MultiVector retainedLoads(Eigen::Index first, Eigen::Index count) const;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace cyclone::rom
