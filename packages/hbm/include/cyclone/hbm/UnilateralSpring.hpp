#pragma once
// Unilateral contact spring f = k max(w - gap, 0): a penalty model of a contact
// that opens (e.g. shroud or underplatform contact in the normal direction).
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

  std::shared_ptr<const ScalarElement> withParameter(const std::string& name, double value) const override;
private:
  double k_, gap_;
};

}  // namespace cyclone::hbm
