#pragma once
// A nonlinear element acting on d relative coordinates w (d = 1 for springs and
// 1D friction, 2 for friction with normal load variation, 3 for friction with
// two tangential directions). The harmonic balance needs only its AFT map
// W -> F between coefficient matrices and the exact Jacobian; the time
// integrator needs the same law one step at a time. Elements with memory
// (friction) compute the Jacobian by carrying the state's sensitivity to the
// coefficients along the time march, which is far cheaper than forming the
// (N d) x (N d) time-domain Jacobian.
#include <Eigen/Dense>
#include <memory>
#include <string>

#include "cyclone/hbm/Aft.hpp"
#include "cyclone/hbm/ElementLinearization.hpp"

namespace cyclone::hbm {

class NonlinearElement {
public:
  virtual ~NonlinearElement() = default;

  /// Number of relative coordinates d the element acts on.
  virtual int dimension() const = 0;
  /// Whether the force depends on the relative velocity.
  virtual bool usesVelocity() const { return false; }
  /// Time samples per period this element needs to resolve its nonsmooth
  /// events (stick/slip, lift-off); 0 if any AFT size will do.
  virtual int recommendedSamples() const { return 0; }

  /// Force coefficients F (nc x d) from relative displacement coefficients
  /// W (nc x d), column c = coordinate c in the Aft's HarmonicSet layout. If
  /// jacobian is given it is set to dvec(F)/dvec(W) ((nc d) x (nc d), index
  /// c * nc + k). omega is the fundamental angular frequency (d/dt = omega d/dtau).
  virtual void harmonicForce(const Aft& aft, const Eigen::MatrixXd& W, double omega, Eigen::MatrixXd& F,
                             Eigen::MatrixXd* jacobian) const = 0;

  /// The Jacobian at W kept as the law's tangent per time sample (ElementLinearization),
  /// for products without the formed matrix; null where the element has none (then
  /// harmonicForce's formed Jacobian is used).
  virtual std::unique_ptr<ElementLinearization> linearization(const Aft& aft, const Eigen::MatrixXd& W,
                                                              double omega) const {
    (void)aft, (void)W, (void)omega;
    return nullptr;
  }
  /// How many numbers its linearization holds at the Aft's samples (what a product
  /// reads), 0 where it has none: ElementJacobians::Automatic takes it only where that is
  /// fewer than the formed Jacobian's (d nc)^2, decided before either is made.
  virtual long linearizationNumbers(const Aft& aft) const {
    (void)aft;
    return 0;
  }

  /// The force at the Aft's time samples (numSamples x d) for the motion W:
  /// the time signal whose harmonics harmonicForce returns, before that
  /// projection (hysteresis loops, contact states). By default the samples of
  /// those harmonics; elements with nonsmooth laws give their own samples.
  virtual Eigen::MatrixXd forceSamples(const Aft& aft, const Eigen::MatrixXd& W, double omega) const;
  /// Size of the internal state carried from step to step by `incremental`.
  virtual int stateSize() const { return 0; }
  /// The state the element starts from (the relaxed element): zeros by default.
  virtual Eigen::VectorXd initialState() const { return Eigen::VectorXd::Zero(stateSize()); }
  /// The same law one time step at a time (for the time-integration check):
  /// force (d) at (w, wdot) given the state of the last converged step;
  /// `state` is updated in place for this trial (the caller keeps the committed
  /// copy). dfdw and dfdwdot are set to d x d.
  virtual Eigen::VectorXd incremental(const Eigen::VectorXd& w, const Eigen::VectorXd& wdot, Eigen::VectorXd& state,
                                      Eigen::MatrixXd& dfdw, Eigen::MatrixXd& dfdwdot) const = 0;
  /// The largest tangent stiffness (d x d) the law takes: what limits an explicit time
  /// step. By default the tangent at the initial state (w = 0); a law whose rest state is
  /// softer than its closed one (a contact with no preload or with a clearance, open at
  /// rest) gives its closed, stuck tangent, or a step sized at rest is unstable the
  /// moment it closes.
  virtual Eigen::MatrixXd stiffestTangent() const;
  /// The same step without its derivatives, f set to d values: what an explicit time
  /// integration calls for every element of every sector at every step (by default
  /// `incremental`; elements with a cheaper force alone override it).
  virtual void stepForce(const Eigen::VectorXd& w, const Eigen::VectorXd& wdot, Eigen::VectorXd& state,
                         Eigen::VectorXd& f) const;

  /// A copy with one named parameter changed (parameter studies and
  /// continuation in it); InputError naming the element's parameters otherwise.
  virtual std::shared_ptr<const NonlinearElement> withParameter(const std::string& name, double value) const;
};

}  // namespace cyclone::hbm
