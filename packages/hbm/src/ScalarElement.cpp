#include "cyclone/hbm/ScalarElement.hpp"

#include "cyclone/core/Error.hpp"

namespace cyclone::hbm {

double ScalarElement::stiffestTangent() const {
  double state = 0, k = 0, kdot = 0;
  incremental(0.0, 0.0, state, k, kdot);
  return k;
}

double ScalarElement::incremental(double w, double wdot, double&, double& dfdw, double& dfdwdot) const {
  Eigen::VectorXd W(1), V(1), f;
  W(0) = w, V(0) = wdot;
  Eigen::MatrixXd dw, dv;
  evaluate(W, V, f, &dw, usesVelocity() ? &dv : nullptr);
  dfdw = dw(0, 0);
  dfdwdot = usesVelocity() ? dv(0, 0) : 0.0;
  return f(0);
}

void ScalarElement::forceSensitivity(const Eigen::VectorXd& w, const Eigen::VectorXd& wdot, const Eigen::MatrixXd& dw,
                                     const Eigen::MatrixXd& dwdot, Eigen::VectorXd& f, Eigen::MatrixXd& df) const {
  const bool velocity = usesVelocity();
  Eigen::MatrixXd dfdw, dfdwdot;
  evaluate(w, wdot, f, &dfdw, velocity ? &dfdwdot : nullptr);
  df.noalias() = dfdw * dw;
  if (velocity) df.noalias() += dfdwdot * dwdot;
}

std::shared_ptr<const ScalarElement> ScalarElement::withParameter(const std::string& name, double) const {
  throw InputError("nonlinear element", "this element has no parameter '" + name + "' to vary");
}

}  // namespace cyclone::hbm
