#pragma once
// Quadratic damper f = c2 wdot |wdot|: velocity-squared (aerodynamic or fluid)
// damping, the velocity-dependent test case of the AFT machinery.
#include "cyclone/hbm/ScalarElement.hpp"

namespace cyclone::hbm {

class QuadraticDamper : public ScalarElement {
public:
  /// c2 >= 0 (a negative value would feed energy in); InputError otherwise.
  explicit QuadraticDamper(double c2);
  double c2() const { return c2_; }
  bool usesVelocity() const override { return true; }
  void evaluate(const Eigen::VectorXd& w, const Eigen::VectorXd& wdot, Eigen::VectorXd& f,
                Eigen::MatrixXd* dfdw, Eigen::MatrixXd* dfdwdot) const override;
  void forceSensitivity(const Eigen::VectorXd& w, const Eigen::VectorXd& wdot, const Eigen::MatrixXd& dw,
                        const Eigen::MatrixXd& dwdot, Eigen::VectorXd& f, Eigen::MatrixXd& df) const override;

  std::shared_ptr<const ScalarElement> withParameter(const std::string& name, double value) const override;
private:
  double c2_;
};

}  // namespace cyclone::hbm
