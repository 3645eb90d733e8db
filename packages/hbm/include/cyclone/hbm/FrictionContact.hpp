#pragma once
// Friction contact with normal load variation and separation (Scalvini 2021, eqs.
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
  /// Samples per period a friction law needs by default (its stick-slip events placed
  /// between samples: the law's error is first order in their spacing).
  static constexpr int kRecommendedSamples = 256;
  int recommendedSamples() const override { return kRecommendedSamples; }
  /// A 2D contact: its law followed in continuous time along the Hermite
  /// interpolant of the motion's samples, every instant (closing, opening, stick,
  /// slip) located between the samples, the harmonics C1 in the motion
  /// (LocatedFrictionForce). A 3D contact: the sampled law, the slider marched over
  /// the samples from the relaxed state (z = 0) until the state at the end of a
  /// period repeats, then one more period recorded; one that can stay stuck all
  /// period rests at the stuck state nearest the relaxed one. Either way the result
  /// (and its mean) is unique and a time shift of the motion shifts the force. The
  /// Jacobian is exact.
  void harmonicForce(const Aft& aft, const Eigen::MatrixXd& W, double omega, Eigen::MatrixXd& F,
                     Eigen::MatrixXd* jacobian) const override;
  /// Force evaluations, process-wide over all contacts, whose slider state did not
  /// settle to a periodic one (period-map mismatch above 1e-14 of the motion after
  /// Newton from two starts): their force is that of a state off the periodic one.
  /// Callers report a count that grew (the forced-response scenes warn); never silent.
  static long unsettledEvaluations();
  /// A 3D contact's Jacobian as the law's tangent per sample of the recorded period
  /// (products equal to the formed Jacobian's to rounding). Null for a 2D contact (the
  /// located law), one open or stuck all period (its formed Jacobian is sparse), and
  /// where the period's start did not settle or is not an isolated fixed point.
  std::unique_ptr<ElementLinearization> linearization(const Aft& aft, const Eigen::MatrixXd& W,
                                                      double omega) const override;
  /// A 3D contact's tangent: a 5 x 5 step matrix per sample; 0 for a 2D contact.
  long linearizationNumbers(const Aft& aft) const override {
    return p_.tangentialDirections == 2 ? 25L * aft.numSamples() : 0;
  }
  /// The sampled contact law itself (stick, slip and lift-off corners intact).
  Eigen::MatrixXd forceSamples(const Aft& aft, const Eigen::MatrixXd& W, double omega) const override;
  int stateSize() const override { return p_.tangentialDirections; }
  Eigen::VectorXd incremental(const Eigen::VectorXd& w, const Eigen::VectorXd& wdot, Eigen::VectorXd& state,
                              Eigen::MatrixXd& dfdw, Eigen::MatrixXd& dfdwdot) const override;
  void stepForce(const Eigen::VectorXd& w, const Eigen::VectorXd& wdot, Eigen::VectorXd& state,
                 Eigen::VectorXd& f) const override;
  /// Stuck and closed: kt on each tangential direction, kn on the normal (with no
  /// preload or a clearance the contact is open at rest, so the rest tangent is zero).
  Eigen::MatrixXd stiffestTangent() const override;
  /// kt, kn, stiffness (kn = kt = value together), mu, preload.
  std::shared_ptr<const NonlinearElement> withParameter(const std::string& name, double value) const override;

private:
  // Samples w (N x d) of the motion W, then the force samples f (N x d) and, if
  // asked, dvec(F)/dvec(W).
  void sampledForce(const Aft& aft, const Eigen::MatrixXd& W, Eigen::MatrixXd& w, Eigen::MatrixXd& f,
                    Eigen::MatrixXd* jacobian) const;
  // 3D contact that never opens and can stay stuck over the whole period: the
  // slider rests at the stuck state nearest the relaxed one (StuckSliderState),
  // not wherever a march that began at sample 0 happened to stop. Fills the
  // samples f (and the Jacobian) and returns true in that case.
  bool stuckThroughout(const Aft& aft, const Eigen::MatrixXd& w, Eigen::MatrixXd& f, Eigen::MatrixXd* jacobian) const;

  FrictionContactParameters p_;
};

}  // namespace cyclone::hbm
