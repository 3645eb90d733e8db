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
  if (!jacobian) {
    element.evaluate(w, wdot, f, nullptr, nullptr);
    return aft.toFrequency(f);
  }
  const Eigen::MatrixXd& e = aft.timeFromCoefficients();
  Eigen::MatrixXd edot, timeJacobian;  // the samples' sensitivities; df/dcoefficients, N x nc
  if (velocity) edot = omega * (e * aft.derivativeMatrix());
  element.forceSensitivity(w, wdot, e, edot, f, timeJacobian);
  *jacobian = aft.coefficientsFromTime() * timeJacobian;
  return aft.toFrequency(f);
}

}  // namespace cyclone::hbm
