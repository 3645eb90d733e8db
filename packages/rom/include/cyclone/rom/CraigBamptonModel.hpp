#pragma once
// The Craig-Bampton model of one nodal diameter: the retained DOFs as the
// boundary and m fixed-interface modes (lowest m distinct natural frequencies
// of the sector with the retained DOFs held; the two real-form copies of a pair
// stay together). On [boundary u_b; modal coordinates q]
//   K_r = [K_g 0; 0 Lambda],  M_r = [M_g M_bm; M_bm^T I],
// and the compliance is the boundary block of ((1 + i eta) K_r - w^2 M_r)^{-1}.
// The damping (1 + i eta) K_r being proportional, (K_r, M_r) is diagonalised once
// and that block is, exactly, sum over all nb + m reduced modes of
// phi_b phi_b^T / ((1 + i eta) l - w^2) (phi_b: the mode's boundary rows): two
// real products per frequency, not an LU. Exact at w = 0 whatever m; converges to
// the full compliance as m grows, natural frequencies from above.
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
  const RetainedModes& modes() const { return modal_.modes(); }
  const HybridFrfModel* modalForm() const override { return &modal_; }
  int numInterfaceModes() const { return int(interface_.size()); }
  /// What it was built from (the HDF5 form stores these): K_g, M_g, M_bm and lambda_j of the modes kept.
  const Eigen::MatrixXd& boundaryStiffness() const { return stiffness_; }
  const Eigen::MatrixXd& boundaryMass() const { return mass_; }
  const Eigen::MatrixXd& massCoupling() const { return coupling_; }
  const Eigen::VectorXd& interfaceEigenvalues() const { return interface_; }
  /// K_r and M_r, boundary first.
  Eigen::MatrixXd reducedStiffness() const;
  Eigen::MatrixXd reducedMass() const;
  double lossFactor() const { return modal_.lossFactor(); }

private:
  Eigen::MatrixXd stiffness_, mass_, coupling_;  // K_g, M_g, M_bm
  Eigen::VectorXd interface_;                    // lambda_j
  HybridFrfModel modal_;  // all nb + m reduced modes at the boundary, no static term: the exact modal form
};

}  // namespace cyclone::rom
