#pragma once
// What the harmonic balance takes from the reduced models of a cyclic sector:
// one ComplianceModel per nodal diameter (real form, copies a and b of the
// retained DOFs), seen as the complex receptance of the travelling wave the
// engine order puts on each harmonic (hbm::ReceptanceModel).
//
// The FE real form holds u_R = Q e^{j phi} u_L, u = u^a + j u^b, phi = 2 pi k / N,
// and its compliance has the block form [P, -Q; Q, P]; for a wave whose
// neighbour moves as e^{j phi} times this sector, U = (P + j Q) F. The
// harmonic balance's neighbour moves as e^{-i 2 pi p / N}: that is k = -p mod N,
// i.e. k = N - p with P + iQ when N - p <= N/2, else k = p with P - iQ (the
// time and the cyclic imaginary units coincide for a travelling wave, and the
// real form of the damped problem commutes with both). k = 0 and N/2 have one copy.
#include <map>
#include <memory>

#include "cyclone/hbm/ModalStiffness.hpp"
#include "cyclone/hbm/ReceptanceModel.hpp"
#include "cyclone/rom/ComplianceModel.hpp"

namespace cyclone::rom {

class SectorReceptance final : public hbm::ReceptanceModel {
public:
  /// models[k]: the reduced model of nodal diameter k (0..N/2), each on the same
  /// retained nodes; only the diameters the harmonics need must be there.
  SectorReceptance(int sectors, std::map<int, std::shared_ptr<const ComplianceModel>> models);

  int numDofs() const override { return dofs_; }
  int sectors() const override { return sectors_; }
  Eigen::MatrixXcd compliance(double frequency, long phaseIndex) const override;
  /// For models with a modal realization A = R / s + U D(w) V^T (R the dropped modes'
  /// constant part): Woodbury's identity (hbm::ModalStiffness), an m x m solve per
  /// frequency instead of an n x n inverse; the LU inverse where R is absent or too
  /// ill conditioned.
  Eigen::MatrixXcd dynamicStiffness(double frequency, long phaseIndex) const override;
  /// Nodal diameter 0's zero-frequency compliance (InputError if that model is missing).
  Eigen::MatrixXd meanCompliance() const override;
  /// The nodal diameter's zero-frequency compliance as the phase's travelling wave
  /// (P + i sign Q of its real form, as compliance()).
  Eigen::MatrixXcd staticCompliance(long phaseIndex) const override;
  /// From the nodal diameter's modal form (none for the full FE model): R the undamped
  /// constant part, U, V the travelling-wave combination of the real-form modes. A
  /// pair's two real-form copies give one travelling-wave mode (their rank-one sum),
  /// so a pair counts once, as it does physically.
  std::optional<hbm::ModalRealization> modalRealization(long phaseIndex) const override;

  /// The nodal diameter and the sign of i Q for a phase index (see the file comment).
  static std::pair<int, int> nodalDiameter(int sectors, long phaseIndex);
  const ComplianceModel& model(int nodalDiameter) const;

private:
  const hbm::ModalStiffness& stiffness(long phaseKey) const;
  mutable std::map<long, hbm::ModalStiffness> stiffness_;
  mutable std::map<long, std::optional<hbm::ModalRealization>> realizations_;
  int sectors_;
  int dofs_ = 0;
  std::map<int, std::shared_ptr<const ComplianceModel>> models_;
};

}  // namespace cyclone::rom
