#pragma once
// A nonlinear element between two scalar coordinates (e.g. a contact point's
// relative displacement), evaluated in the time domain over one period. The
// AFT scheme only needs forces and their sensitivities at the samples, so
// every element, with or without memory, fits this one interface.
#include <Eigen/Dense>
#include <memory>
#include <string>

namespace cyclone::hbm {

class ScalarElement {
public:
  virtual ~ScalarElement() = default;

  /// Whether the force depends on the velocity (callers may then skip
  /// computing velocity samples: wdot is passed empty).
  virtual bool usesVelocity() const { return false; }
  /// As NonlinearElement::recommendedSamples: 0 if any AFT size will do.
  virtual int recommendedSamples() const { return 0; }

  /// Force samples f[n] over one period from relative displacement samples
  /// w[n] and velocity samples wdot[n] = dw/dt (= omega dw/dtau), n = 0..N-1,
  /// the samples being a periodic steady state. If given, dfdw and dfdwdot
  /// are resized to N x N with entries df[n]/dw[m], df[n]/dwdot[m] (diagonal
  /// for memoryless elements, full for hysteretic ones).
  virtual void evaluate(const Eigen::VectorXd& w, const Eigen::VectorXd& wdot, Eigen::VectorXd& f,
                        Eigen::MatrixXd* dfdw, Eigen::MatrixXd* dfdwdot) const = 0;

  /// The law's own force at each sample (a hysteresis loop's points, the contact
  /// states): evaluate()'s samples, unless they are not the law at the samples but what
  /// its harmonics are taken from (UnilateralSpring: the instants located between them).
  virtual void lawSamples(const Eigen::VectorXd& w, const Eigen::VectorXd& wdot, Eigen::VectorXd& f) const {
    evaluate(w, wdot, f, nullptr, nullptr);
  }

  /// The force samples f and their sensitivity df = dfdw dw + dfdwdot dwdot (N x m) to
  /// m quantities the samples depend on, given dw (N x m) and dwdot (N x m; empty when
  /// the element does not use the velocity). The AFT Jacobian needs only this product
  /// (the quantities: the Fourier coefficients); the default forms evaluate()'s N x N
  /// matrices, O(N^2 m), the elements here override it with O(N m) (at N = 1024 the
  /// difference is 36 ms against 0.3 ms per Jacobian).
  virtual void forceSensitivity(const Eigen::VectorXd& w, const Eigen::VectorXd& wdot, const Eigen::MatrixXd& dw,
                                const Eigen::MatrixXd& dwdot, Eigen::VectorXd& f, Eigen::MatrixXd& df) const;

  /// The same law, one time step at a time (for the time-integration check):
  /// force at (w, wdot) given the element's internal state from the last
  /// converged step; `state` is updated in place for the trial (the caller keeps
  /// the committed copy). Memoryless elements use evaluate() on one sample.
  virtual double incremental(double w, double wdot, double& state, double& dfdw, double& dfdwdot) const;
  /// The largest tangent stiffness the law takes (NonlinearElement::stiffestTangent): by
  /// default its tangent at rest.
  virtual double stiffestTangent() const;

  /// A copy with one named parameter changed; InputError if it has no such parameter.
  virtual std::shared_ptr<const ScalarElement> withParameter(const std::string& name, double value) const;
};

}  // namespace cyclone::hbm
