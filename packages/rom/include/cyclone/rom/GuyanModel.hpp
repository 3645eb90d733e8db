#pragma once
// Guyan's model (static condensation) of one nodal diameter at the retained
// DOFs: K_g = K_bb - K_bi K_ii^{-1} K_ib and M_g = Psi^T M Psi from a
// BoundaryReduction, and
//   A(w) = ((1 + i eta) K_g - w^2 M_g)^{-1},
// evaluated in its own modal form: (K_g, M_g) diagonalised once, and the damping
// (1 + i eta) K_g being proportional, A(w) = sum over all its modes of
// phi phi^T / ((1 + i eta) l - w^2) exactly (two real products per frequency, not an LU).
// Exact at w = 0 (K_g^{-1} is the boundary block of K^{-1}); above it the
// interior inertia is only carried along statically, so its natural frequencies
// lie above the full model's (Rayleigh-Ritz) and its resonances come too high.
#include "cyclone/rom/BoundaryReduction.hpp"
#include "cyclone/rom/ComplianceModel.hpp"
#include "cyclone/rom/HybridFrfModel.hpp"

namespace cyclone::rom {

class GuyanModel final : public ComplianceModel {
public:
  GuyanModel(const BoundaryReduction& reduction, double lossFactor);

  Eigen::Index size() const override { return stiffness_.rows(); }
  Eigen::MatrixXcd compliance(double omega) const override;
  /// K_g^{-1}; InputError for a free sector (rigid-body modes).
  Eigen::MatrixXd zeroFrequencyCompliance() const override;

  /// The eigenpairs of (K_g, M_g): one per retained DOF, mass-normalised.
  const RetainedModes& modes() const { return modal_.modes(); }
  const HybridFrfModel* modalForm() const override { return &modal_; }
  const Eigen::MatrixXd& stiffness() const { return stiffness_; }
  const Eigen::MatrixXd& mass() const { return mass_; }
  double lossFactor() const { return modal_.lossFactor(); }

private:
  Eigen::MatrixXd stiffness_, mass_;
  HybridFrfModel modal_;  // all the model's modes, no static term: its exact modal form
};

}  // namespace cyclone::rom
