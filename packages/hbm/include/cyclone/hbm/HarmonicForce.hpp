#pragma once
// Harmonic balance form of a scalar element: the AFT map from the harmonic
// coefficients of the relative displacement to those of the force,
// F(W) = P f(E W, omega E D W), with its exact coefficient Jacobian
// dF/dW = P (df/dw) E + omega P (df/dwdot) E D.
#include "cyclone/hbm/Aft.hpp"
#include "cyclone/hbm/ScalarElement.hpp"

#include <Eigen/Dense>

namespace cyclone::hbm {

/// Force coefficients (nc) of `element` under relative displacement
/// coefficients wCoefficients (nc, the Aft's HarmonicSet layout). omega is the
/// fundamental angular frequency, used only by velocity-dependent elements
/// (dw/dt = omega dw/dtau). If jacobian is given it is set to dF/dW (nc x nc).
/// The time-domain Jacobian is N x N, so keep N moderate when asking for it.
Eigen::VectorXd harmonicForce(const ScalarElement& element, const Aft& aft, const Eigen::VectorXd& wCoefficients,
                              Eigen::MatrixXd* jacobian = nullptr, double omega = 1.0);

}  // namespace cyclone::hbm
