#pragma once
// Jenkins element: a spring kt in series with a Coulomb slider of slip force
// mu N. The standard macroslip model of a friction contact in the tangential
// direction; it has memory (hysteresis), so the force at a sample depends on
// the whole history, and the Jacobian df[n]/dw[m] is full.
#include "cyclone/hbm/ScalarElement.hpp"

namespace cyclone::hbm {

class JenkinsElement : public ScalarElement {
public:
  /// kt > 0, slipForce > 0; InputError otherwise.
  JenkinsElement(double kt, double slipForce);
  double tangentialStiffness() const { return kt_; }
  double slipForce() const { return slipForce_; }

  /// Marches the slider from z = 0 over two periods of the samples (the first
  /// one settles the hysteresis loop) and returns the second. The Jacobian
  /// differentiates that marching exactly, so it matches finite differences
  /// away from samples that sit exactly on a stick/slip transition.
  void evaluate(const Eigen::VectorXd& w, const Eigen::VectorXd& wdot, Eigen::VectorXd& f,
                Eigen::MatrixXd* dfdw, Eigen::MatrixXd* dfdwdot) const override;
  void forceSensitivity(const Eigen::VectorXd& w, const Eigen::VectorXd& wdot, const Eigen::MatrixXd& dw,
                        const Eigen::MatrixXd& dwdot, Eigen::VectorXd& f, Eigen::MatrixXd& df) const override;
  /// One time step of the same law: state = slider position z (0 initially).
  double incremental(double w, double wdot, double& state, double& dfdw, double& dfdwdot) const override;

  std::shared_ptr<const ScalarElement> withParameter(const std::string& name, double value) const override;
private:
  double kt_, slipForce_;
};

}  // namespace cyclone::hbm
