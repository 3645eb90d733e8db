#include "cyclone/hbm/UnilateralSpring.hpp"

#include <memory>

#include "LocatedUnilateralForce.hpp"
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
  if (dfdw) dfdw->setZero(n, n);
  const Eigen::VectorXd g = k_ * (w.array() - gap_).matrix();
  detail::locatedUnilateralForce(g, f, [&](Eigen::Index i, Eigen::Index j, double ii, double ij, double ji, double jj) {
    if (!dfdw) return;
    (*dfdw)(i, i) += k_ * ii, (*dfdw)(i, j) += k_ * ij, (*dfdw)(j, i) += k_ * ji, (*dfdw)(j, j) += k_ * jj;
  });
  if (dfdwdot) dfdwdot->setZero(n, n);
}

void UnilateralSpring::forceSensitivity(const Eigen::VectorXd& w, const Eigen::VectorXd&, const Eigen::MatrixXd& dw,
                                        const Eigen::MatrixXd&, Eigen::VectorXd& f, Eigen::MatrixXd& df) const {
  const Eigen::VectorXd g = k_ * (w.array() - gap_).matrix();
  df.setZero(dw.rows(), dw.cols());
  detail::locatedUnilateralForce(g, f, [&](Eigen::Index i, Eigen::Index j, double ii, double ij, double ji, double jj) {
    df.row(i) += k_ * (ii * dw.row(i) + ij * dw.row(j));
    df.row(j) += k_ * (ji * dw.row(i) + jj * dw.row(j));
  });
}

void UnilateralSpring::lawSamples(const Eigen::VectorXd& w, const Eigen::VectorXd&, Eigen::VectorXd& f) const {
  f = (k_ * (w.array() - gap_).max(0.0)).matrix();
}

double UnilateralSpring::incremental(double w, double, double&, double& dfdw, double& dfdwdot) const {
  const double penetration = w - gap_;
  dfdw = penetration > 0 ? k_ : 0.0, dfdwdot = 0;
  return penetration > 0 ? k_ * penetration : 0.0;
}

std::shared_ptr<const ScalarElement> UnilateralSpring::withParameter(const std::string& name, double value) const {
  if (name == "k") return std::make_shared<UnilateralSpring>(value, gap_);
  if (name == "gap") return std::make_shared<UnilateralSpring>(k_, value);
  throw InputError("nonlinear element", "unknown parameter '" + name + "' (k, gap)");
}

}  // namespace cyclone::hbm
