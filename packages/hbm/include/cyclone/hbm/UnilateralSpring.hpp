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
  /// A contact's force has a spectrum that decays slowly, so its samples grow with the
  /// harmonics (HarmonicSet::nonsmoothSamples), from 64, and an incomplete curve is traced
  /// again with more: with 64 at H = 7 and 12 a two-resonance oscillator hammering at one
  /// of them had no start at the range's start and a wall (traced whole with 128).
  int recommendedSamples() const override { return 64; }
  void evaluate(const Eigen::VectorXd& w, const Eigen::VectorXd& wdot, Eigen::VectorXd& f,
                Eigen::MatrixXd* dfdw, Eigen::MatrixXd* dfdwdot) const override;
  void forceSensitivity(const Eigen::VectorXd& w, const Eigen::VectorXd& wdot, const Eigen::MatrixXd& dw,
                        const Eigen::MatrixXd& dwdot, Eigen::VectorXd& f, Eigen::MatrixXd& df) const override;
  /// The law itself at each sample (evaluate() locates the instants between them).
  void lawSamples(const Eigen::VectorXd& w, const Eigen::VectorXd& wdot, Eigen::VectorXd& f) const override;
  /// The law itself at one instant (the time integration's).
  double incremental(double w, double wdot, double& state, double& dfdw, double& dfdwdot) const override;
  /// Closed: k (with a gap the spring is open at rest).
  double stiffestTangent() const override { return k_; }

  std::shared_ptr<const ScalarElement> withParameter(const std::string& name, double value) const override;
private:
  double k_, gap_;
};

}  // namespace cyclone::hbm
