#pragma once
// Friction contact with normal load variation and separation (seed eqs.
// 7.17-7.20; Petrov & Ewins, Yang & Menq): a normal penalty spring kn with
// preload N0 and, in series with the tangential spring kt, a Coulomb slider
// whose limit mu N(t) follows the instantaneous normal load. With two
// tangential directions the friction limit is a circle (the slip direction is
// the direction of the trial force), which two independent 1D sliders would
// miss: they dissipate differently under elliptic or circular relative motion.
//
// Relative coordinates w = [t1, (t2), n]: tangential slips, then the normal
// approach (positive = pressing together). Normal force N = max(N0 + kn n, 0):
// the contact opens when n < -N0 / kn (N0 < 0 is a clearance of -N0 / kn).
// While open the tangential force is zero and the slider follows, so the
// contact recloses without stored tangential stretch.
#include "cyclone/hbm/NonlinearElement.hpp"

namespace cyclone::hbm {

struct FrictionContactParameters {
  int tangentialDirections = 1;  ///< 1 (2D contact) or 2 (3D contact)
  double kt = 0;                 ///< tangential stiffness, > 0
  double kn = 0;                 ///< normal stiffness, >= 0 (0: constant normal load N0 > 0)
  double mu = 0;                 ///< friction coefficient, >= 0
  double preload = 0;            ///< N0: normal force at n = 0
};

class FrictionContact : public NonlinearElement {
public:
  /// InputError naming the parameter when one is out of range.
  explicit FrictionContact(const FrictionContactParameters& p);
  const FrictionContactParameters& parameters() const { return p_; }

  int dimension() const override { return p_.tangentialDirections + 1; }
  int recommendedSamples() const override { return 256; }
  /// Marches the slider over the samples from the relaxed state (z = 0) until
  /// the state at the end of a period repeats, then records one more period,
  /// so the result (and its mean) is unique; the Jacobian differentiates that
  /// march exactly.
  void harmonicForce(const Aft& aft, const Eigen::MatrixXd& W, double omega, Eigen::MatrixXd& F,
                     Eigen::MatrixXd* jacobian) const override;
  int stateSize() const override { return p_.tangentialDirections; }
  Eigen::VectorXd incremental(const Eigen::VectorXd& w, const Eigen::VectorXd& wdot, Eigen::VectorXd& state,
                              Eigen::MatrixXd& dfdw, Eigen::MatrixXd& dfdwdot) const override;
  /// kt, kn, mu, preload.
  std::shared_ptr<const NonlinearElement> withParameter(const std::string& name, double value) const override;

private:
  FrictionContactParameters p_;
};

}  // namespace cyclone::hbm
