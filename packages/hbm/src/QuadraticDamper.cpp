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

void QuadraticDamper::forceSensitivity(const Eigen::VectorXd& w, const Eigen::VectorXd& wdot, const Eigen::MatrixXd&,
                                       const Eigen::MatrixXd& dwdot, Eigen::VectorXd& f, Eigen::MatrixXd& df) const {
  if (wdot.size() != w.size() || dwdot.rows() != w.size())
    throw InputError("QuadraticDamper", "needs " + std::to_string(w.size()) + " velocity samples and their sensitivities, got " +
                                            std::to_string(wdot.size()));
  f = c2_ * wdot.array() * wdot.array().abs();
  df = (2.0 * c2_ * wdot.array().abs()).matrix().asDiagonal() * dwdot;
}

std::shared_ptr<const ScalarElement> QuadraticDamper::withParameter(const std::string& name, double value) const {
  if (name == "c2") return std::make_shared<QuadraticDamper>(value);
  throw InputError("nonlinear element", "unknown parameter '" + name + "' (c2)");
}

}  // namespace cyclone::hbm
