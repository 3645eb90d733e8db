#pragma once
// A receptance model seen through other coordinates: q = T x + T_next x_next,
// x_next the neighbouring sector's DOFs of a cyclic model (ReceptanceModel's
// convention: x_next = e^{-i 2 pi p / N} x for phase index p). For phase p,
// T_p = T + e^{-i 2 pi p / N} T_next, and a force f on q acts on x as T_p^H f
// (sector 0 also carries the reaction of the element joining sector N-1 to it),
// so
//   A_q(w, p) = T_p A(w, p) T_p^H.
// Petrov's condensed harmonic balance (Scalvini 2021, ch. 7): q are the contacts' relative
// displacements plus the excited and observed DOFs, usually far fewer than the
// retained DOFs, and every force of the system acts on q.
#include <map>
#include <memory>

#include "cyclone/hbm/ModalStiffness.hpp"
#include "cyclone/hbm/ReceptanceModel.hpp"

namespace cyclone::hbm {

class ProjectedReceptance final : public ReceptanceModel {
public:
  /// T and T_next: q rows by the base model's DOFs (T_next empty: zero). InputError
  /// when the sizes do not fit or T_next is given for a model that is not cyclic.
  ProjectedReceptance(std::shared_ptr<const ReceptanceModel> base, Eigen::MatrixXd T, Eigen::MatrixXd Tnext = {});
  int numDofs() const override { return int(T_.rows()); }
  int sectors() const override { return base_->sectors(); }
  Eigen::MatrixXcd compliance(double frequency, long phaseIndex) const override;
  /// By Woodbury's identity over the projected modal realization where it is usable
  /// (q x q x modes per frequency instead of an LU inverse), else the plain inverse.
  Eigen::MatrixXcd dynamicStiffness(double frequency, long phaseIndex) const override;
  /// Whether dynamicStiffness takes Woodbury's identity for phase p.
  bool usesWoodbury(long phaseIndex) const { return projected(phaseIndex).stiffness.usable(); }
  /// Woodbury's parts where usesWoodbury(p) (kept with the projection), else nullptr.
  const ModalStiffness* modalStiffness(long phaseIndex) const override;
  /// T_0 A_mean T_0^T, T_0 = T + T_next (the mean motion is the same in every sector).
  Eigen::MatrixXd meanCompliance() const override;
  /// The base model's realization projected: R' = T_p R T_p^H, U' = T_p U, V' = conj(T_p) V
  /// (computed once per phase: Hill's method asks for it at every point).
  std::optional<ModalRealization> modalRealization(long phaseIndex) const override;
  /// T_p (q rows by the base model's DOFs).
  Eigen::MatrixXcd transform(long phaseIndex) const;
  const ReceptanceModel& base() const { return *base_; }

private:
  // Per phase index: the projected modal realization when it reproduces the projected
  // compliance (checked once against it), so that a frequency costs q x q x modes
  // instead of the base model's n x n compliance and two n-wide products.
  // With it, the dynamic stiffness by Woodbury's identity where that holds.
  struct Projected {
    bool hasRealization = false;  // the base model has one (then r is its projection)
    bool usable = false;
    ModalRealization r;
    ModalStiffness stiffness;
  };
  const Projected& projected(long phaseIndex) const;
  std::optional<ModalRealization> projectedRealization(long phaseIndex) const;
  Eigen::MatrixXcd projectedDirectly(double frequency, long phaseIndex) const;
  std::shared_ptr<const ReceptanceModel> base_;
  Eigen::MatrixXd T_, Tnext_;
  mutable std::map<long, Projected> projected_;
};

}  // namespace cyclone::hbm
