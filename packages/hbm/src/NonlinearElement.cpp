#include "cyclone/hbm/NonlinearElement.hpp"

#include "cyclone/core/Error.hpp"

namespace cyclone::hbm {

Eigen::MatrixXd NonlinearElement::forceSamples(const Aft& aft, const Eigen::MatrixXd& W, double omega) const {
  Eigen::MatrixXd F;
  harmonicForce(aft, W, omega, F, nullptr);
  Eigen::MatrixXd f(aft.numSamples(), F.cols());
  for (Eigen::Index c = 0; c < F.cols(); ++c) aft.toTime(F.col(c).data(), f.col(c).data());
  return f;
}

Eigen::MatrixXd NonlinearElement::stiffestTangent() const {
  const int d = dimension();
  Eigen::VectorXd state = initialState(), zero = Eigen::VectorXd::Zero(d);
  Eigen::MatrixXd k, kdot;
  incremental(zero, zero, state, k, kdot);
  return k;
}

void NonlinearElement::stepForce(const Eigen::VectorXd& w, const Eigen::VectorXd& wdot, Eigen::VectorXd& state,
                                 Eigen::VectorXd& f) const {
  Eigen::MatrixXd dfdw, dfdwdot;
  f = incremental(w, wdot, state, dfdw, dfdwdot);
}

std::shared_ptr<const NonlinearElement> NonlinearElement::withParameter(const std::string& name, double) const {
  throw InputError("nonlinear element", "this element has no parameter '" + name + "' to vary");
}

}  // namespace cyclone::hbm
