#include "cyclone/hbm/CubicSpring.hpp"

#include <memory>

#include "cyclone/core/Error.hpp"

#include <cmath>
#include <string>

namespace cyclone::hbm {

CubicSpring::CubicSpring(double k3) : k3_(k3) {
  if (!std::isfinite(k3)) throw InputError("CubicSpring", "k3 must be finite, got " + std::to_string(k3));
}

void CubicSpring::evaluate(const Eigen::VectorXd& w, const Eigen::VectorXd&, Eigen::VectorXd& f,
                           Eigen::MatrixXd* dfdw, Eigen::MatrixXd* dfdwdot) const {
  const Eigen::Index n = w.size();
  f = k3_ * w.array().cube();
  if (dfdw) {
    dfdw->setZero(n, n);
    dfdw->diagonal() = 3.0 * k3_ * w.array().square();
  }
  if (dfdwdot) dfdwdot->setZero(n, n);
}

void CubicSpring::forceSensitivity(const Eigen::VectorXd& w, const Eigen::VectorXd&, const Eigen::MatrixXd& dw,
                                   const Eigen::MatrixXd&, Eigen::VectorXd& f, Eigen::MatrixXd& df) const {
  f = k3_ * w.array().cube();
  df = (3.0 * k3_ * w.array().square()).matrix().asDiagonal() * dw;
}

std::shared_ptr<const ScalarElement> CubicSpring::withParameter(const std::string& name, double value) const {
  if (name == "k3") return std::make_shared<CubicSpring>(value);
  throw InputError("nonlinear element", "unknown parameter '" + name + "' (k3)");
}

}  // namespace cyclone::hbm
