#pragma once
// A scalar element (spring, damper, Jenkins) seen as a one-coordinate
// NonlinearElement, so the harmonic balance system and the time integrator
// handle every element through one interface.
#include <memory>

#include "cyclone/hbm/NonlinearElement.hpp"
#include "cyclone/hbm/ScalarElement.hpp"

namespace cyclone::hbm {

class ScalarElementAdapter : public NonlinearElement {
public:
  explicit ScalarElementAdapter(std::shared_ptr<const ScalarElement> element);
  const ScalarElement& scalar() const { return *element_; }

  int dimension() const override { return 1; }
  bool usesVelocity() const override { return element_->usesVelocity(); }
  int recommendedSamples() const override { return element_->recommendedSamples(); }
  void harmonicForce(const Aft& aft, const Eigen::MatrixXd& W, double omega, Eigen::MatrixXd& F,
                     Eigen::MatrixXd* jacobian) const override;
  /// The scalar law applied to the sampled motion (a Jenkins element's loop with sharp
  /// stick-slip corners, not its truncated Fourier series).
  Eigen::MatrixXd forceSamples(const Aft& aft, const Eigen::MatrixXd& W, double omega) const override;
  int stateSize() const override { return 1; }
  Eigen::VectorXd incremental(const Eigen::VectorXd& w, const Eigen::VectorXd& wdot, Eigen::VectorXd& state,
                              Eigen::MatrixXd& dfdw, Eigen::MatrixXd& dfdwdot) const override;
  std::shared_ptr<const NonlinearElement> withParameter(const std::string& name, double value) const override;
  Eigen::MatrixXd stiffestTangent() const override { return Eigen::MatrixXd::Constant(1, 1, element_->stiffestTangent()); }

private:
  std::shared_ptr<const ScalarElement> element_;
};

}  // namespace cyclone::hbm
