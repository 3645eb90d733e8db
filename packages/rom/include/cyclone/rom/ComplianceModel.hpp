#pragma once
// What a reduced model hands to the harmonic balance: the dynamic compliance
// at its retained DOFs for a frequency, whatever kind of model it is (the full
// FE reference, the hybrid FRF model, modal truncation). Eigen only.
//
// Retained DOF order: index = copy * (DOFs per copy) + DOF, copy 0 and 1 being
// the real and imaginary parts of the cyclic real form at nodal diameter k (one
// copy for k = 0 and N/2), the DOFs of a copy node by node, each node's chosen
// directions in order (RetainedDofs.hpp); with all 3 global directions, index =
// (copy * retainedNodes + node) * 3 + direction. The complex entries are the
// time-harmonic amplitudes x = A(omega) f for f e^{i omega t}.
#include <Eigen/Dense>

namespace cyclone::rom {

class HybridFrfModel;

class ComplianceModel {
public:
  virtual ~ComplianceModel() = default;
  /// Rows and columns of the compliance: 3 x retained nodes x copies.
  virtual Eigen::Index size() const = 0;
  /// A(omega) (complex symmetric), omega in rad/s.
  virtual Eigen::MatrixXcd compliance(double omega) const = 0;
  /// A(omega) X for a block of real columns X (size() rows): what a check by a few probe
  /// vectors needs. By default the formed compliance times X; the full FE model solves
  /// for the block alone (a factorization and a solve per column, not per retained DOF).
  virtual Eigen::MatrixXcd complianceTimes(double omega, const Eigen::MatrixXd& X) const {
    return compliance(omega) * X.cast<std::complex<double>>();
  }
  /// The undamped compliance at omega = 0 (real): what the mean (harmonic 0) of a
  /// harmonic balance solution sees. Structural damping has no meaning at zero
  /// frequency, so this is not compliance(0). InputError for a model with rigid-body modes.
  virtual Eigen::MatrixXd zeroFrequencyCompliance() const = 0;

  /// Load patterns the model carries (its excitation part): 0 unless built with some.
  virtual Eigen::Index numLoads() const { return 0; }
  /// x_r(omega) = A_rf(omega) f: the retained DOFs' response to each load pattern (one
  /// column each). InputError for a model without load patterns.
  virtual Eigen::MatrixXcd loadResponse(double omega) const;
  /// The model as modes plus a constant part, when it is one (hybrid, truncation, and
  /// Guyan and Craig-Bampton through their reduced modes): what Hill's method uses.
  /// Null for the full FE compliance.
  virtual const HybridFrfModel* modalForm() const { return nullptr; }
};

}  // namespace cyclone::rom
