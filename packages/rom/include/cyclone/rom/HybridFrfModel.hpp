#pragma once
// The hybrid FRF model (Petrov, "A high-accuracy model reduction for analysis of nonlinear vibrations in structures with contact interfaces", J. Eng. Gas Turbines Power 2011; Scalvini 2021, eqs. 5.27-5.35) and plain modal
// truncation at the retained DOFs of one nodal diameter, with structural
// damping (1 + i eta) K on every mode:
//   truncation: A(w) = sum_j phi_j phi_j^T / ((1 + i eta) l_j - w^2)
//   hybrid:     A(w) = A0 / (1 + i eta)
//                    + sum_j phi_j phi_j^T [1 / ((1 + i eta) l_j - w^2) - 1 / ((1 + i eta)(l_j - sigma))]
// with l_j = w_j^2 and A0 = G^T (K - sigma M)^{-1} G the exact real compliance at
// the shift sigma = w0^2 from one factorization. With all modes kept the hybrid
// model is the exact compliance G^T ((1 + i eta) K - w^2 M)^{-1} G; truncated, it
// misses sum over dropped modes of phi phi^T (w^2 - (1 + i eta) sigma) / (...),
// which falls like (w / w_dropped)^2. Petrov's form expands about w0^2 itself
// and needs the complex A0 = G^T ((1 + i eta) K - w0^2 M)^{-1} G; ours expands
// about (1 + i eta) w0^2, where A0 is real up to 1 / (1 + i eta). For w0 = 0
// the two are identical. Using an undamped A0
// (what CalculiX's *GREEN gives) in Petrov's damped formula, as Scalvini 2021 did,
// adds sum over all modes of i eta l_j phi_j phi_j^T / ((l_j - w0^2)((1 + i eta) l_j - w0^2)),
// about i eta A0: large against A(w) between resonances, whatever the modes kept.
#include <string>
#include <vector>

#include "cyclone/rom/ComplianceModel.hpp"

namespace cyclone::rom {

/// Modes of the full model seen at the retained DOFs.
struct RetainedModes {
  int copies = 1;
  std::vector<double> eigenvalues;  ///< omega_j^2 in (rad/s)^2, ascending; pairs listed twice
  Eigen::MatrixXd shapes;           ///< retained DOFs x modes, from mass-normalised modes
  Eigen::MatrixXd loads;            ///< modes x load patterns: phi_j^T f (empty: no load patterns)
  double seconds = 0;               ///< eigen-solution time

  int numModes() const { return int(eigenvalues.size()); }
  /// The lowest `distinct` natural frequencies (a pair counts once: its two real-form copies stay together).
  RetainedModes first(int distinct) const;
  /// Eigenvalues below 1e-6 of the largest computed one: rigid-body motions.
  int numRigidBodyModes() const;
};

/// The exact static (shifted) compliance at the retained DOFs: G^T (K - sigma M)^{-1} G.
struct StaticCompliance {
  double omega0 = 0;      ///< requested expansion frequency (rad/s)
  double shift = 0;       ///< sigma actually used, (rad/s)^2 (= omega0^2 unless shifted automatically)
  Eigen::MatrixXd matrix; ///< retained DOFs x retained DOFs
  Eigen::MatrixXd loadResponse;  ///< retained DOFs x load patterns: G^T (K - sigma M)^{-1} f (same factorization)
  std::string note;       ///< how sigma was chosen (an automatic shift is reported here and in the log)
  double seconds = 0;     ///< factorization and solves
};

class HybridFrfModel final : public ComplianceModel {
public:
  /// Hybrid model: modes and the static compliance of the same model (same size).
  HybridFrfModel(RetainedModes modes, StaticCompliance staticCompliance, double lossFactor);
  /// Modal truncation: the modes alone (no static correction).
  static HybridFrfModel modalTruncation(RetainedModes modes, double lossFactor);

  Eigen::Index size() const override { return modes_.shapes.rows(); }
  Eigen::MatrixXcd compliance(double omega) const override;
  Eigen::MatrixXd zeroFrequencyCompliance() const override;
  /// The excitation part (Scalvini 2021, eqs. 5.27-5.35) for loads off the retained DOFs, with the
  /// same weights as the compliance: A0_rf f / (1 + i eta) + Phi diag(w_j(omega)) (Phi^T f);
  /// exact with all modes, its truncation error that of the compliance.
  Eigen::Index numLoads() const override { return modes_.loads.cols(); }
  Eigen::MatrixXcd loadResponse(double omega) const override;

  const HybridFrfModel* modalForm() const override { return this; }
  bool hasStaticCorrection() const { return hasStatic_; }
  /// The split A(w) = R + Phi diag(d(w)) Phi^T: R = A0 / (1 + i eta) - Phi diag(1 / ((1 + i eta)(l_j - sigma))) Phi^T
  /// is the part of the modes not kept (constant in w; zero for a truncation), d_j(w) = 1 / ((1 + i eta) l_j - w^2).
  Eigen::MatrixXcd residualCompliance() const;
  Eigen::VectorXcd modalWeights(double omega) const;
  const RetainedModes& modes() const { return modes_; }
  const StaticCompliance& staticCompliance() const { return static_; }
  double lossFactor() const { return eta_; }

private:
  HybridFrfModel(RetainedModes modes, double lossFactor);
  // Per mode: 1 / ((1 + i eta) l_j - w^2), less 1 / ((1 + i eta)(l_j - sigma)) with the static correction.
  Eigen::VectorXcd expansionWeights(double omega) const;
  RetainedModes modes_;
  StaticCompliance static_;
  bool hasStatic_ = false;
  double eta_ = 0;
};

}  // namespace cyclone::rom
