#include "cyclone/hbm/ScalarElement.hpp"

#include "cyclone/core/Error.hpp"

namespace cyclone::hbm {

double ScalarElement::incremental(double w, double wdot, double&, double& dfdw, double& dfdwdot) const {
  Eigen::VectorXd W(1), V(1), f;
  W(0) = w, V(0) = wdot;
  Eigen::MatrixXd dw, dv;
  evaluate(W, V, f, &dw, usesVelocity() ? &dv : nullptr);
  dfdw = dw(0, 0);
  dfdwdot = usesVelocity() ? dv(0, 0) : 0.0;
  return f(0);
}

std::shared_ptr<const ScalarElement> ScalarElement::withParameter(const std::string& name, double) const {
  throw InputError("nonlinear element", "this element has no parameter '" + name + "' to vary");
}

}  // namespace cyclone::hbm
