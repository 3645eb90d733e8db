#include "cyclone/hbm/ScalarElementAdapter.hpp"

#include "cyclone/core/Error.hpp"
#include "cyclone/hbm/HarmonicForce.hpp"

namespace cyclone::hbm {

ScalarElementAdapter::ScalarElementAdapter(std::shared_ptr<const ScalarElement> element) : element_(std::move(element)) {
  if (!element_) throw InputError("nonlinear element", "no element given");
}

Eigen::MatrixXd ScalarElementAdapter::forceSamples(const Aft& aft, const Eigen::MatrixXd& W, double omega) const {
  const Eigen::VectorXd wCoefficients = W.col(0);
  const Eigen::VectorXd w = aft.toTime(wCoefficients);
  Eigen::VectorXd wdot, f;
  if (element_->usesVelocity()) wdot = aft.toTime(Eigen::VectorXd(omega * (aft.derivativeMatrix() * wCoefficients)));
  element_->lawSamples(w, wdot, f);
  return f;
}

void ScalarElementAdapter::harmonicForce(const Aft& aft, const Eigen::MatrixXd& W, double omega, Eigen::MatrixXd& F,
                                         Eigen::MatrixXd* jacobian) const {
  F = hbm::harmonicForce(*element_, aft, Eigen::VectorXd(W.col(0)), jacobian, omega);
}

Eigen::VectorXd ScalarElementAdapter::incremental(const Eigen::VectorXd& w, const Eigen::VectorXd& wdot,
                                                  Eigen::VectorXd& state, Eigen::MatrixXd& dfdw,
                                                  Eigen::MatrixXd& dfdwdot) const {
  double dw = 0, dv = 0;
  Eigen::VectorXd f(1);
  f(0) = element_->incremental(w(0), wdot.size() ? wdot(0) : 0.0, state(0), dw, dv);
  dfdw = Eigen::MatrixXd::Constant(1, 1, dw);
  dfdwdot = Eigen::MatrixXd::Constant(1, 1, dv);
  return f;
}

std::shared_ptr<const NonlinearElement> ScalarElementAdapter::withParameter(const std::string& name,
                                                                       double value) const {
  return std::make_shared<ScalarElementAdapter>(element_->withParameter(name, value));
}

}  // namespace cyclone::hbm
