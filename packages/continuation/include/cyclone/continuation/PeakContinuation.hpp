#pragma once
// The resonance peak continued in a parameter by LOCA, for systems whose Jacobian
// jumps (friction through AFT: each stick-slip instant crossing a time sample), on the
// peak condition with the response eliminated (Petrov's direct parametric analysis,
// reduced to the frequency). The continuation's unknown is the peak frequency alone:
//   G(w; q) = d ln m / d ln w  along the frequency curve at p = p(q)  = 0,
// q = ln p (or p), m(x) the response measure, x(w, p) the system's solution at (w, p)
// by Newton; G and its derivative in ln w are differences of ln m over the solutions at
// ln w +- {1, 3} h / 2, and LOCA continues G / |dG / d ln w| (the distance to the peak in
// ln w, to first order) so that its tolerance is a relative frequency. LOCA (ArclengthContinuation's Loca
// engine) continues the one equation in (w, q) by arclength, so folds of the peak curve
// in p are passed.
//
// Why this and not trackPeak's bordered system in (x, w): there, Newton works on the
// whole x and at every sample crossing the Jacobian it linearises jumps, so the
// corrector cycles between the pieces and the continuation creeps (5000 points short of
// the range, docs/decisions.md). Here each (w, p) is solved by a Newton of its own (which
// passes those corners, as PeakSearch's does), and the continuation sees only G: a
// continuous function of (w, q) whose slope changes slightly at a crossing. The price
// is five solves per evaluation of G (the centre and four sides); each starts from the
// solutions already made (the centre by a secant through the two nearest, the sides
// from the centre along the frequency curve's tangent).
#include <Eigen/Dense>
#include <string>

#include "cyclone/continuation/PeakFollowing.hpp"
#include "cyclone/continuation/PeakTracking.hpp"

namespace cyclone::continuation {

struct PeakContinuationOptions {
  double from = 0, to = 0;     ///< the parameter range; the start's peak is at `from` (either direction)
  bool logarithmic = true;     ///< continued in q = ln p (p > 0; decades of a preload evenly); else in p
  /// h: G from the solutions at ln w +- {1, 3} h / 2. Wide enough that G's bends at
  /// sample crossings stay small beside its slope, narrow beside the peak's width: the
  /// Jenkins oscillator's peak over its slip force with 1024 samples was continued whole
  /// at 1e-3 (40 points; 3e-3 biased the peaks by 4.7e-4, 5e-4 crept), at 256 samples
  /// by none of them (docs/decisions.md).
  double frequencyStep = 1e-3;
  double tolerance = 1e-10;    ///< Newton at each (w, p): ||R||_2
  int maxNewtonIterations = 50;
  /// LOCA's corrector: |G| / |dG / d ln w| (the distance to the peak in ln w, to first
  /// order) at most this.
  double conditionTolerance = 1e-7;
  /// LOCA's arclength steps in (w / w0, q): initial, smallest, largest (0: the range in q
  /// over 12).
  double initialStep = 0.02, minStep = 1e-7, maxStep = 0;
  int maxSteps = 400;
  bool locateOptimum = true;   ///< the smallest peak, by golden section in q between its neighbours
  double optimumTolerance = 1e-4;  ///< the golden section's bracket in q (relative in p when logarithmic)
};

/// The peak of the frequency curve through (x0, w0) at p = options.from (x0 a solution or
/// a close guess near the peak: the peak is first found at `from`), continued to
/// options.to. The points are LOCA's continuation steps (jump = false), in the order
/// traced; `searches` counts LOCA's steps and `solves` the Newton solves at fixed (w, p);
/// the optimum is the smallest peak (located when inside the range and asked for).
/// `complete` when the range's end was reached, else stopReason says where and why.
FollowedPeakCurve continuePeak(const PeakTrackingProblem& problem, const Eigen::VectorXd& x0, double w0,
                               const PeakContinuationOptions& options);

}  // namespace cyclone::continuation
