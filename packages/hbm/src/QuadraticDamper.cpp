#include "cyclone/hbm/QuadraticDamper.hpp"

#include <memory>

#include "cyclone/core/Error.hpp"

#include <cmath>
#include <string>

namespace cyclone::hbm {

QuadraticDamper::QuadraticDamper(double c2) : c2_(c2) {
  if (!(std::isfinite(c2) && c2 >= 0))
    throw InputError("QuadraticDamper", "c2 must be finite and non-negative, got " + std::to_string(c2));
}

void QuadraticDamper::evaluate(const Eigen::VectorXd& w, const Eigen::VectorXd& wdot, Eigen::VectorXd& f,
                               Eigen::MatrixXd* dfdw, Eigen::MatrixXd* dfdwdot) const {
  if (wdot.size() != w.size())
    throw InputError("QuadraticDamper", "needs " + std::to_string(w.size()) + " velocity samples, got " +
                                            std::to_string(wdot.size()));
  const Eigen::Index n = w.size();
  f = c2_ * wdot.array() * wdot.array().abs();
  if (dfdw) dfdw->setZero(n, n);
  if (dfdwdot) {
    dfdwdot->setZero(n, n);
    dfdwdot->diagonal() = 2.0 * c2_ * wdot.array().abs();
  }
}

std::shared_ptr<const ScalarElement> QuadraticDamper::withParameter(const std::string& name, double value) const {
  if (name == "c2") return std::make_shared<QuadraticDamper>(value);
  throw InputError("nonlinear element", "unknown parameter '" + name + "' (c2)");
}

}  // namespace cyclone::hbm
