#pragma once
// Cubic spring f = k3 w^3: the Duffing nonlinearity, the smooth reference case
// whose harmonics are known exactly (cos^3 = 3/4 cos + 1/4 cos 3).
#include "cyclone/hbm/ScalarElement.hpp"

namespace cyclone::hbm {

class CubicSpring : public ScalarElement {
public:
  /// k3 of either sign (softening when negative); InputError if not finite.
  explicit CubicSpring(double k3);
  double k3() const { return k3_; }
  void evaluate(const Eigen::VectorXd& w, const Eigen::VectorXd& wdot, Eigen::VectorXd& f,
                Eigen::MatrixXd* dfdw, Eigen::MatrixXd* dfdwdot) const override;
  void forceSensitivity(const Eigen::VectorXd& w, const Eigen::VectorXd& wdot, const Eigen::MatrixXd& dw,
                        const Eigen::MatrixXd& dwdot, Eigen::VectorXd& f, Eigen::MatrixXd& df) const override;

  std::shared_ptr<const ScalarElement> withParameter(const std::string& name, double value) const override;
private:
  double k3_;
};

}  // namespace cyclone::hbm
