#pragma once
// The tuned full ring's compliance from one cyclic sector's: the inverse cyclic transform.
// A cyclic sector's model answers per inter-sector phase index p (hbm::ReceptanceModel:
// sector j+1 moves as e^{-i 2 pi p / N} times sector j). Forces F_k on the ring's sectors
// split into waves F_k = sum_p G_p e^{-i 2 pi p k / N}, G_p = (1/N) sum_k F_k e^{+i 2 pi p k / N},
// each answered by A(w, p); so sector j's response to sector k's force is
//   A_ring(j, k)(w) = (1/N) sum_p A(w, p) e^{-i 2 pi p (j - k) / N},
// block circulant (it depends on j - k mod N), and the same transform of the phases'
// dynamic stiffnesses is its inverse, of their static compliances its mean (harmonic 0)
// compliance. Each sector's DOFs are in that sector's own frame (sector 0's turned by
// j 2 pi / N), as the cyclic model's are, so the sector's elements and excitation carry
// over sector by sector (ReducedSectorRing.hpp).
//
// The ring's modal realization is every phase's modes times its phase pattern:
//   U_ring(j, (p, m)) = U_p(:, m) e^{-i 2 pi p j / N} / sqrt(N),
//   V_ring(k, (p, m)) = V_p(:, m) e^{+i 2 pi p k / N} / sqrt(N),
// eigenvalue l_{p,m}, and R_ring the transform of the phases' constant parts. Mistuning
// (a component-mode model: SNM, CMM) enters there: a blade-to-blade stiffness scatter
// projected on these tuned ring modes adds a full (not diagonal) matrix dK to diag(l), the
// modal part becoming U ((1 + i eta)(diag(l) + dK) - w^2 I)^{-1} V^T, while R_ring and the
// contact and excitation DOFs stay as they are.
#include <memory>
#include <optional>

#include "cyclone/hbm/ReceptanceModel.hpp"

namespace cyclone::mistuning {

class RingReceptance final : public hbm::ReceptanceModel {
public:
  /// `sector`: a cyclic model (N >= 2) answering every phase index 0..N-1 (for a disc's
  /// reduced models: every nodal diameter 0..N/2). Its static compliance of every phase is
  /// formed here (the ring's mean compliance): InputError, with the sector model's key and
  /// the phase, where one is missing.
  explicit RingReceptance(std::shared_ptr<const hbm::ReceptanceModel> sector);

  /// N n: sector j's DOFs at j n .. j n + n - 1.
  int numDofs() const override { return N_ * n_; }
  int sectors() const override { return 1; }
  int ringSectors() const { return N_; }
  int sectorDofs() const { return n_; }
  const hbm::ReceptanceModel& sector() const { return *sector_; }

  /// Phase index 0 only (the ring is not cyclic; Error for another).
  Eigen::MatrixXcd compliance(double frequency, long phaseIndex) const override;
  /// The transform of every phase's dynamic stiffness (exact: the inverse of a block
  /// circulant matrix is the block circulant of its phases' inverses).
  Eigen::MatrixXcd dynamicStiffness(double frequency, long phaseIndex) const override;
  Eigen::MatrixXd meanCompliance() const override { return mean_; }
  /// The ring's modal realization (see the file comment) when every phase has one with the
  /// same loss factor, else none.
  std::optional<hbm::ModalRealization> modalRealization(long phaseIndex) const override;

  /// sum_p B_p e^{-i 2 pi p (j - k) / N} / N into block (j, k): the transform of N phase
  /// matrices (n x n each, phase p at index p) into the ring's N n square matrix.
  static Eigen::MatrixXcd ringMatrix(const std::vector<Eigen::MatrixXcd>& phases);

private:
  void requirePhaseZero(long phaseIndex) const;
  std::shared_ptr<const hbm::ReceptanceModel> sector_;
  int N_ = 0, n_ = 0;
  Eigen::MatrixXd mean_;
  mutable bool realized_ = false;
  mutable std::optional<hbm::ModalRealization> realization_;
};

}  // namespace cyclone::mistuning
