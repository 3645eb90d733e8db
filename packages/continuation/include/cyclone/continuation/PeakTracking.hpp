#pragma once
// The resonance peak of a frequency response followed in a parameter p (Petrov,
// "Direct parametric analysis of resonance regimes for nonlinear vibrations of
// bladed disks", J. Turbomach. 2007): one continuation gives the peak against the
// preload, the friction coefficient, the force..., through folds in p, instead of a
// frequency curve per value.
//
// Unknowns y = (x, w) (w in units of `frequencyUnit`), parameter p, equations
//   R(x, w; p) = 0                                the system at frequency w,
//   g(x, w; p) = (w / m) grad m(x) . z = 0,      J z = -dR/dw,
// z the frequency curve's tangent dx/dw at fixed p (J = dR/dx), m(x) a smooth response
// measure (e.g. the squared first-harmonic amplitude of a DOF): g is d ln m / d ln w
// along the frequency curve, dimensionless and zero exactly at its peaks (and troughs).
// The bordered Jacobian [[J, dR/dw], [dg/dx, dg/dw]] needs second derivatives of R,
// which are contracted without forming them: with J^T lambda = grad m,
//   grad m . dz = -lambda . (dJ z + d(dR/dw)),
// lambda . (dJ/dx_i) z = (J(x + eps z)^T lambda - J(x)^T lambda)_i / eps and
// lambda . d(dR/dw)/dx_i = (J(x, w + d)^T lambda - J(x, w)^T lambda)_i / d (symmetry of
// the second derivatives): three Jacobians, one factorization and two solves per
// evaluation, any engine (ArclengthContinuation.hpp) tracing the extended system.
#include <functional>

#include "cyclone/continuation/ArclengthContinuation.hpp"

namespace cyclone::continuation {

struct PeakTrackingProblem {
  int size = 0;  ///< unknowns x
  std::function<void(const Eigen::VectorXd& x, double w, double p, Eigen::VectorXd& R)> residual;
  std::function<void(const Eigen::VectorXd& x, double w, double p, Eigen::MatrixXd& J)> jacobian;  ///< dR/dx
  /// m(x) > 0 near the peak, its gradient, and its Hessian times a vector.
  std::function<double(const Eigen::VectorXd& x)> measure;
  std::function<Eigen::VectorXd(const Eigen::VectorXd& x)> measureGradient;
  std::function<Eigen::VectorXd(const Eigen::VectorXd& x, const Eigen::VectorXd& v)> measureHessianTimes;
  double frequencyUnit = 1;  ///< w = frequencyUnit * y(size): the frequency unknown of order one
  /// 0: g from the tangent J z = -dR/dw (smooth systems). > 0: for systems whose Jacobian
  /// jumps (friction: each stick-slip instant crossing a time sample), where that g jumps
  /// too and no corrector converges: g = (w / m) (m(x+) - m(x-)) / (2 h w), x+- the
  /// solutions at w (1 +- h) from x, a function of w alone on the curve, continuous; its
  /// Jacobian row [0, dg/dw] by differences of the same kind.
  double solutionStep = 0;
  std::vector<int> scaleGroups;  ///< per unknown x, as ContinuationProblem::scaleGroups (empty: one)
  /// The cos and sin coefficients (indices into x) of the response whose phase
  /// atan2(x_s, x_c) parametrises the frequency curve near the peak (continuePeak): it
  /// turns monotonically through a resonance, also where the curve folds in w.
  int phaseCosIndex = -1, phaseSinIndex = -1;
};

/// The extended system in y = (x, w / frequencyUnit) and p, for traceBranch.
ContinuationProblem peakCondition(const PeakTrackingProblem& problem);

/// The measure m(x) = (x_c^2 + x_s^2) of two coefficients (a DOF's cos and sin of one
/// harmonic): squared amplitude, with its gradient and Hessian; their phase is the
/// problem's phase (phaseCosIndex, phaseSinIndex).
void useSquaredAmplitude(PeakTrackingProblem& problem, int cosIndex, int sinIndex);

struct TrackedPeak {
  double parameter = 0, frequency = 0, measure = 0;
  Eigen::VectorXd x;
};

struct PeakCurve {
  std::vector<TrackedPeak> points;
  bool finished = false;
  BranchEnd end = BranchEnd::Running;  ///< how the extended system's branch ended (stopReason: as a sentence)
  std::string stopReason;
  ContinuationStatistics statistics;
};

/// Follows the peak from (x0, w0), a point on or near it at p = options.from (Newton on
/// the extended system corrects it first), to options.to.
PeakCurve trackPeak(const PeakTrackingProblem& problem, const Eigen::VectorXd& x0, double w0,
                    const ContinuationOptions& options);

}  // namespace cyclone::continuation
