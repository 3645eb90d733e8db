#pragma once
// Damping given per mode: every mode of (K, M) damped by the same ratio of critical, the
// matrix a matrix scene's modal_damping_ratio adds to C and the Python package's
// cyclone.modal_damping returns (one computation, so both give the same C to the bit).
#include <Eigen/Dense>

namespace cyclone::hbm {

/// C = M Phi diag(2 zeta w_j) Phi^T M, Phi the M-normalised modes of (K, M) and w_j their
/// frequencies: Phi^T C Phi = diag(2 zeta w_j). InputError("modal damping") when zeta < 0,
/// M is not positive definite or K has a negative eigenvalue.
Eigen::MatrixXd modalDamping(const Eigen::MatrixXd& M, const Eigen::MatrixXd& K, double zeta);

}  // namespace cyclone::hbm
