#include "cyclone/hbm/UnilateralSpring.hpp"

#include <memory>

#include "cyclone/core/Error.hpp"

#include <cmath>
#include <string>

namespace cyclone::hbm {

UnilateralSpring::UnilateralSpring(double k, double gap) : k_(k), gap_(gap) {
  if (!(std::isfinite(k) && k >= 0))
    throw InputError("UnilateralSpring", "stiffness must be finite and non-negative, got " + std::to_string(k));
  if (!std::isfinite(gap)) throw InputError("UnilateralSpring", "gap must be finite, got " + std::to_string(gap));
}

void UnilateralSpring::evaluate(const Eigen::VectorXd& w, const Eigen::VectorXd&, Eigen::VectorXd& f,
                                Eigen::MatrixXd* dfdw, Eigen::MatrixXd* dfdwdot) const {
  const Eigen::Index n = w.size();
  f.resize(n);
  if (dfdw) dfdw->setZero(n, n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const double penetration = w[i] - gap_;
    const bool closed = penetration > 0;
    f[i] = closed ? k_ * penetration : 0.0;
    if (dfdw && closed) (*dfdw)(i, i) = k_;  // one-sided: 0 exactly at contact onset
  }
  if (dfdwdot) dfdwdot->setZero(n, n);
}

void UnilateralSpring::forceSensitivity(const Eigen::VectorXd& w, const Eigen::VectorXd&, const Eigen::MatrixXd& dw,
                                        const Eigen::MatrixXd&, Eigen::VectorXd& f, Eigen::MatrixXd& df) const {
  const Eigen::ArrayXd penetration = w.array() - gap_;
  const Eigen::ArrayXd closed = (penetration > 0).cast<double>();  // one-sided: 0 exactly at onset
  f = (k_ * closed * penetration).matrix();
  df = (k_ * closed).matrix().asDiagonal() * dw;
}

std::shared_ptr<const ScalarElement> UnilateralSpring::withParameter(const std::string& name, double value) const {
  if (name == "k") return std::make_shared<UnilateralSpring>(value, gap_);
  if (name == "gap") return std::make_shared<UnilateralSpring>(k_, value);
  throw InputError("nonlinear element", "unknown parameter '" + name + "' (k, gap)");
}

}  // namespace cyclone::hbm
