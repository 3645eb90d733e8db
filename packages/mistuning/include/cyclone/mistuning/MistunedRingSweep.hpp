#pragma once
// The linear forced response of a mistuned ring by the subset of nominal modes
// (SubsetOfNominalModes.hpp) over a frequency sweep, cheap enough for a Monte Carlo over
// patterns. The engine-order load puts F e^{-i 2 pi EO j / N} on blade j's excitation DOF
// (sector j's DOF `excitationDof`, RingReceptance's order: every blade delayed by
// j 2 pi EO / N), and blade j's response is sector j's `responseDof`. What does not change
// with the pattern is formed once: the tuned realization's rows at the response DOFs, its
// constant part's response R f, the modal load V^T f, and each blade's projected stiffness
// B_j = dK of the unit deviation on blade j, so a pattern's dK = sum_j delta_j B_j. With no
// viscous modal damping (structural loss factor only) the modal dynamic stiffness is
// (1 + i eta)(diag(l) + dK) - w^2 I: one Hermitian eigendecomposition of diag(l) + dK per
// pattern, then per frequency N m operations; with viscous damping a dense m x m LU per
// frequency. Either way the same response as MistunedRingReceptance's compliance applied
// to the load, at the response rows.
#include <complex>
#include <vector>

#include <Eigen/Dense>

#include "cyclone/hbm/ReceptanceModel.hpp"
#include "cyclone/mistuning/LumpedRing.hpp"

namespace cyclone::mistuning {

class MistunedRingSweep {
public:
  /// `tuned`: the tuned ring's modal realization (RingReceptance::modalRealization(0)) of
  /// `sectors` sectors of `sectorDofs` retained DOFs each; `modesPerPhase` and
  /// `bladeProjection` as subsetOfNominalModesStiffness takes them. Error where the sizes
  /// disagree, InputError naming mistuning/engine_order or mistuning/excitation_dof where
  /// those are out of range.
  MistunedRingSweep(const hbm::ModalRealization& tuned, int sectors, int sectorDofs,
                    const std::vector<int>& modesPerPhase, const Eigen::MatrixXcd& bladeProjection,
                    int engineOrder, int excitationDof, int responseDof, std::complex<double> force = 1.0);

  int blades() const { return N_; }
  int engineOrder() const { return eo_; }
  /// The ring's load vector (N n): F e^{-i 2 pi EO j / N} at sector j's excitation DOF.
  const Eigen::VectorXcd& load() const { return f_; }
  /// B_j: the modal stiffness perturbation of a unit deviation on blade j.
  const Eigen::MatrixXcd& bladeMatrix(int j) const { return B_[std::size_t(j)]; }
  /// dK = sum_j delta_j B_j (InputError naming mistuning/youngs_modulus_factors for a
  /// wrong length).
  Eigen::MatrixXcd stiffnessPerturbation(const std::vector<double>& delta) const;

  /// Blade responses, N x omegas.size(): column k at omegas[k] (rad/s).
  Eigen::MatrixXcd responses(const std::vector<double>& delta, const std::vector<double>& omegas) const;
  /// Each blade's peak over the sweep, and the localisation (inverse participation ratio)
  /// of the response at the worst blade's peak.
  BladePeaks peaks(const std::vector<double>& delta, const std::vector<double>& omegas) const;

private:
  int N_ = 0, n_ = 0, eo_ = 0, resp_ = 0;
  double eta_ = 0;
  bool viscous_ = false;
  Eigen::VectorXd l_, c_;
  Eigen::MatrixXcd Ur_;   ///< U at the response rows (N x m)
  Eigen::VectorXcd r0_;   ///< (R f) at the response rows, undamped
  Eigen::VectorXcd g_;    ///< V^T f
  Eigen::VectorXcd f_;
  std::vector<Eigen::MatrixXcd> B_;
};

}  // namespace cyclone::mistuning
