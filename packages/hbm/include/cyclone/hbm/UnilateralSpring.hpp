#pragma once
// Unilateral contact spring f = k max(w - gap, 0): a penalty model of a contact
// that opens (e.g. shroud or underplatform contact in the normal direction). Its
// harmonic force locates the opening and closing instants between the time samples
// (LocatedUnilateralForce.hpp): smooth in the motion where the sampled law kinks.
#include "cyclone/hbm/ScalarElement.hpp"

namespace cyclone::hbm {

class UnilateralSpring : public ScalarElement {
public:
  /// k >= 0; gap < 0 means interference (preloaded contact at w = 0).
  UnilateralSpring(double k, double gap);
  double stiffness() const { return k_; }
  double gap() const { return gap_; }
  void evaluate(const Eigen::VectorXd& w, const Eigen::VectorXd& wdot, Eigen::VectorXd& f,
                Eigen::MatrixXd* dfdw, Eigen::MatrixXd* dfdwdot) const override;
  void forceSensitivity(const Eigen::VectorXd& w, const Eigen::VectorXd& wdot, const Eigen::MatrixXd& dw,
                        const Eigen::MatrixXd& dwdot, Eigen::VectorXd& f, Eigen::MatrixXd& df) const override;
  /// The law itself at each sample (evaluate() locates the instants between them).
  void lawSamples(const Eigen::VectorXd& w, const Eigen::VectorXd& wdot, Eigen::VectorXd& f) const override;
  /// The law itself at one instant (the time integration's).
  double incremental(double w, double wdot, double& state, double& dfdw, double& dfdwdot) const override;

  std::shared_ptr<const ScalarElement> withParameter(const std::string& name, double value) const override;
private:
  double k_, gap_;
};

}  // namespace cyclone::hbm
