#pragma once
// The mistuned ring by the subset of nominal modes (SNM; Yang & Griffin 2001), with no
// full-ring FE solve. The tuned ring's modes are every phase's sector modes times their
// phase pattern (RingReceptance.hpp):
//   Phi_ring(j, (p, a)) = Phi_p(:, a) e^{-i 2 pi p j / N} / sqrt(N),
// Phi_p the sector's mass-normalised complex shapes of phase p (Phi_p^H M_p Phi_p = I), at
// the retained DOFs U_p = G Phi_p and V_p = conj(U_p). Blade j's stiffness scaled by
// f_j = 1 + delta_j adds delta_j K_blade on sector j, which projected on those modes is
//   dK((p, a), (q, b)) = (1/N) sum_j delta_j e^{i 2 pi (p - q) j / N} (Phi_p^H K_blade Phi_q)(a, b),
// K_blade the stiffness of the sector's blade elements (the same in every sector's own
// frame). The mistuned ring's compliance at its retained DOFs is then
//   A(w) = R / (1 + i eta) + U ((1 + i eta)(diag(l) + dK) + i w diag(c) - w^2 I)^{-1} V^T,
// U, V, l, c, R, eta the tuned ring's modal realization. The approximations: the kept modes
// span the mistuned modes (exact with every mode; in practice the family's modes of every
// nodal diameter, and the error grows with the scatter and the nearness of other
// families), and the constant part R, the static correction of the modes not kept, stays
// the tuned one. The retained DOFs (contacts, excitation) stay physical, so the friction
// elements and the excitation attach as in the tuned ring.
#include <memory>
#include <optional>
#include <vector>

#include <Eigen/Dense>

#include "cyclone/hbm/ReceptanceModel.hpp"

namespace cyclone::mistuning {

/// dK above: `modesPerPhase[p]` modes of phase p in RingReceptance's order (phase by phase),
/// `bladeProjection` = Phi^H K_blade Phi over the sector's shapes of every phase stacked in
/// that order (sum m_p square), `deviations` delta_j per blade (N = its size =
/// modesPerPhase' size). Exactly zero for zero deviations. InputError naming
/// mistuning/youngs_modulus_factors for a wrong number of deviations.
Eigen::MatrixXcd subsetOfNominalModesStiffness(const std::vector<int>& modesPerPhase,
                                               const Eigen::MatrixXcd& bladeProjection,
                                               const std::vector<double>& deviations);

/// The mistuned ring's receptance (phase index 0 only: the ring is not cyclic).
class MistunedRingReceptance final : public hbm::ReceptanceModel {
public:
  /// `tuned`: the tuned ring's modal realization (RingReceptance::modalRealization(0));
  /// `dK`: its modal stiffness perturbation (m x m, Hermitian up to rounding).
  MistunedRingReceptance(hbm::ModalRealization tuned, Eigen::MatrixXcd dK);
  int numDofs() const override { return int(tuned_.U.rows()); }
  int sectors() const override { return 1; }
  Eigen::MatrixXcd compliance(double frequency, long phaseIndex) const override;
  /// The undamped static compliance R + U (diag(l) + dK)^{-1} V^T (real part).
  Eigen::MatrixXd meanCompliance() const override { return mean_; }
  /// None: the modal part is not diagonal (Hill's method on the ring would need one).
  std::optional<hbm::ModalRealization> modalRealization(long) const override { return std::nullopt; }

  const hbm::ModalRealization& tuned() const { return tuned_; }
  const Eigen::MatrixXcd& stiffnessPerturbation() const { return dK_; }
  /// The mistuned ring's undamped modes in the reduced basis: eigenvalues of diag(l) + dK,
  /// ascending (rad/s)^2, and the modes at the retained DOFs, U y (y orthonormal).
  struct Modes {
    Eigen::VectorXd eigenvalues;
    Eigen::MatrixXcd retained;
  };
  Modes modes() const;

private:
  void requirePhaseZero(long phaseIndex) const;
  hbm::ModalRealization tuned_;
  Eigen::MatrixXcd dK_;
  Eigen::MatrixXd mean_;
};

}  // namespace cyclone::mistuning
