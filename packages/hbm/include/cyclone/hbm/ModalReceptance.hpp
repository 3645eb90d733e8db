#pragma once
// A receptance given by its modal realizations (ReceptanceModel.hpp), one per
// inter-sector phase index: the model a time integration can take as it is.
// `causalModalModel` makes one from any model with modal forms:
//   - its modes kept;
//   - the constant part R (the static correction of the modes not kept) either
//     dropped, or realized by modes of its own at a frequency w_r far above the
//     response's: R = sum_k s_k q_k q_k^H (its eigenpairs, s_k > 0), each a mode with
//     l = w_r^2 and U V^T = s_k w_r^2 q_k q_k^H, whose compliance s_k q_k q_k^H / (1 - w^2 / w_r^2)
//     is R's to (w / w_r)^2. Kept as a constant, the displacement at the contacts would
//     follow the contact force at the same instant: an implicit loop over the whole
//     ring at every time step;
//   - the structural loss factor eta made modal viscous damping c_j = eta w_j, equal to
//     it at each mode's own frequency: structural damping has no causal time-domain form
//     (a response at -w would need 1 - i eta).
// The harmonic balance on this model and a time integration of it are then the same
// equations: the reference the friction-damped disc's harmonic balance is checked
// against in the time domain (hbm/TravellingWaveIntegration.hpp).
#include <map>
#include <memory>
#include <vector>

#include "cyclone/hbm/ReceptanceModel.hpp"

namespace cyclone::hbm {

class ModalReceptance final : public ReceptanceModel {
public:
  /// `realizations` by phase index 0..N-1; a phase p whose N - p is given but not p
  /// itself is that one's conjugate (the ring is real). InputError where sizes differ.
  ModalReceptance(int sectors, std::map<long, ModalRealization> realizations);
  int numDofs() const override { return dofs_; }
  int sectors() const override { return sectors_; }
  /// R / (1 + i eta) + U diag(1 / ((1 + i eta) l + i c w - w^2)) V^T; InputError for a
  /// phase the model lacks.
  Eigen::MatrixXcd compliance(double frequency, long phaseIndex) const override;
  /// The phase-0 compliance at zero frequency, R + U diag(1 / l) V^T (real part).
  Eigen::MatrixXd meanCompliance() const override;
  std::optional<ModalRealization> modalRealization(long phaseIndex) const override;
  /// Whether the model has phase p (directly or as its conjugate's).
  bool hasPhase(long phaseIndex) const;

private:
  const ModalRealization& realization(long phaseIndex) const;
  int sectors_ = 1, dofs_ = 0;
  std::map<long, ModalRealization> byPhase_;
};

/// The causal modal model of `model` at the given phases (and their conjugates): see the
/// file comment; residualFrequency w_r (rad/s) > 0 realizes the constant part by modes
/// at w_r, 0 drops it. InputError naming the phase where the model has no modal form,
/// or for a constant part that is not Hermitian positive semi-definite.
std::shared_ptr<ModalReceptance> causalModalModel(const ReceptanceModel& model, const std::vector<long>& phases,
                                                  double residualFrequency = 0);

}  // namespace cyclone::hbm
