#include "cyclone/hbm/ScalarElement.hpp"

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

}  // namespace cyclone::hbm
