#pragma once
// The Craig-Bampton model of one harmonic index: the retained DOFs as the
// boundary and m fixed-interface modes (lowest m distinct natural frequencies
// of the sector with the retained DOFs held; the two real-form copies of a pair
// stay together). On [boundary u_b; modal coordinates q]
//   K_r = [K_g 0; 0 Lambda],  M_r = [M_g M_bm; M_bm^T I],
// and the compliance is the boundary block of ((1 + i eta) K_r - w^2 M_r)^{-1}.
// Lambda being diagonal, that block is the inverse of the Schur complement
//   (1 + i eta) K_g - w^2 M_g - w^4 M_bm diag(1 / ((1 + i eta) lambda_j - w^2)) M_bm^T,
// one dense LU of the boundary size per frequency. Exact at w = 0 whatever m;
// converges to the full compliance as m grows, natural frequencies from above.
#include "cyclone/rom/BoundaryReduction.hpp"
#include "cyclone/rom/ComplianceModel.hpp"
#include "cyclone/rom/HybridFrfModel.hpp"

namespace cyclone::rom {

class CraigBamptonModel final : public ComplianceModel {
public:
  /// The lowest `fixedInterfaceModes` distinct interface frequencies of `reduction`
  /// (InputError naming "fixed_interface_modes" if < 1 or more than it holds).
  CraigBamptonModel(const BoundaryReduction& reduction, int fixedInterfaceModes, double lossFactor);

  Eigen::Index size() const override { return stiffness_.rows(); }
  Eigen::MatrixXcd compliance(double omega) const override;
  /// K_g^{-1} (the modal block does not couple in K_r); InputError for a free sector.
  Eigen::MatrixXd zeroFrequencyCompliance() const override;

  /// The eigenpairs of (K_r, M_r) (boundary + modal coordinates), mass-normalised,
  /// shapes restricted to the boundary (retained) DOFs.
  RetainedModes modes() const;
  int numInterfaceModes() const { return int(interface_.size()); }
  /// K_r and M_r, boundary first.
  Eigen::MatrixXd reducedStiffness() const;
  Eigen::MatrixXd reducedMass() const;
  double lossFactor() const { return eta_; }

private:
  Eigen::MatrixXd stiffness_, mass_, coupling_;  // K_g, M_g, M_bm
  Eigen::VectorXd interface_;                    // lambda_j
  int copies_ = 1;
  double eta_ = 0;
};

}  // namespace cyclone::rom
