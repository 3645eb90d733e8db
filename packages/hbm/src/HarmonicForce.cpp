#include "cyclone/hbm/HarmonicForce.hpp"

#include "cyclone/core/Error.hpp"

#include <string>

namespace cyclone::hbm {

Eigen::VectorXd harmonicForce(const ScalarElement& element, const Aft& aft, const Eigen::VectorXd& wCoefficients,
                              Eigen::MatrixXd* jacobian, double omega) {
  const int nc = aft.numCoefficients();
  if (wCoefficients.size() != nc)
    throw InputError("harmonicForce", "expected " + std::to_string(nc) + " coefficients, got " +
                                          std::to_string(wCoefficients.size()));
  const Eigen::VectorXd w = aft.toTime(wCoefficients);
  Eigen::VectorXd wdot;
  const bool velocity = element.usesVelocity();
  if (velocity) wdot = aft.toTime(Eigen::VectorXd(omega * (aft.derivativeMatrix() * wCoefficients)));

  Eigen::VectorXd f;
  Eigen::MatrixXd dfdw, dfdwdot;
  element.evaluate(w, wdot, f, jacobian ? &dfdw : nullptr, jacobian && velocity ? &dfdwdot : nullptr);
  if (jacobian) {
    const Eigen::MatrixXd& e = aft.timeFromCoefficients();
    const Eigen::MatrixXd& p = aft.coefficientsFromTime();
    Eigen::MatrixXd timeJacobian = dfdw * e;  // N x nc
    if (velocity) timeJacobian.noalias() += omega * (dfdwdot * (e * aft.derivativeMatrix()));
    *jacobian = p * timeJacobian;
  }
  return aft.toFrequency(f);
}

}  // namespace cyclone::hbm
