#pragma once
// The resonance peak continued in a parameter by LOCA, for systems whose Jacobian
// jumps (friction through AFT: each stick-slip instant crossing a time sample), on the
// peak condition with the response eliminated (Petrov's direct parametric analysis,
// reduced to one unknown). The frequency curve is parametrised near its peak by the
// phase phi of the response's fundamental (problem.phaseCosIndex, phaseSinIndex), not by
// the frequency: the phase turns monotonically through a resonance, also where the
// curve folds in w (a friction-damped shroud's curve folds twice within 1e-3 of its
// peak's frequency, and solves at fixed w there did not converge), and a peak spans
// about one radian of phase whatever its damping, so one phase step fits sharp and flat
// peaks. The continuation's unknown is the peak's phase:
//   G(phi; q) = d ln m / d phi  along the frequency curve at p = p(q)  = 0,
// q = ln p (or p), m(x) the response measure, (x, w)(phi, p) the system's solution at
// phase phi by Newton (the system bordered with the phase condition); G is the
// difference of ln m over the solutions at phi +- h, its derivative that of the sides'
// slopes d ln m / d phi (each through the curve's tangent there), and LOCA continues G /
// |dG / d phi| (the distance to the peak in phase, to first order). LOCA
// (ArclengthContinuation's Loca engine) continues the one equation in (phi, q) by
// arclength, so folds of the peak curve in p are passed. G's zero is the peak to the
// stencil's bias (h^2 c^2 / 12 in ln w for a linear resonance of damping ratio c / 2),
// and of the envelope where the top is a chain of micro-folds (the disc's shroud at
// low preload, a local maximum every 0.03-0.1 Hz, 1e-3 apart).
//
// Why this and not trackPeak's bordered system in (x, w): there, Newton works on the
// whole x and at every sample crossing the Jacobian it linearises jumps, so the
// corrector cycles between the pieces and the continuation creeps (5000 points short of
// the range, docs/decisions.md). Here each (phi, p) is solved by a Newton of its own
// (which passes those corners, as PeakSearch's does), and the continuation sees only G:
// a continuous function of (phi, q) whose slope changes slightly at a crossing. The
// price is two solves and two tangents per evaluation of G; each solve starts from the
// solutions already made (by a secant through the two nearest, or along the tangent of
// the other side).
#include <Eigen/Dense>
#include <string>

#include "cyclone/continuation/PeakFollowing.hpp"
#include "cyclone/continuation/PeakTracking.hpp"

namespace cyclone::continuation {

struct PeakContinuationOptions {
  double from = 0, to = 0;     ///< the parameter range; the start's peak is at `from` (either direction)
  bool logarithmic = true;     ///< continued in q = ln p (p > 0; decades of a preload evenly); else in p
  /// h (radians): G from the solutions at phi +- h. Wide enough that G's bends at sample
  /// crossings stay small beside its slope (about -1 at a peak), narrow beside the peak's
  /// width of about one radian.
  double phaseStep = 0.1;
  double tolerance = 1e-10;    ///< Newton at each (phi, p): ||(R, phase condition)||_2
  int maxNewtonIterations = 50;
  /// LOCA's corrector: |G| / |dG / d phi| (the distance to the peak in phase, radians, to
  /// first order) at most this.
  double conditionTolerance = 1e-5;
  /// LOCA's arclength steps in (phi, q): initial, smallest, largest (0: the range in q
  /// over 12).
  double initialStep = 0.02, minStep = 1e-7, maxStep = 0;
  int maxSteps = 400;
  bool locateOptimum = true;   ///< the smallest peak, by golden section in q between its neighbours
  double optimumTolerance = 1e-4;  ///< the golden section's bracket in q (relative in p when logarithmic)
};

/// The peak of the frequency curve through (x0, w0) at p = options.from (x0 a solution or
/// a close guess near the peak, solved at w0 first: the peak is then found at `from` from
/// its phase), continued to
/// options.to. The points are LOCA's continuation steps (jump = false), in the order
/// traced; `searches` counts LOCA's steps and `solves` the Newton solves at fixed (w, p);
/// the optimum is the smallest peak (located when inside the range and asked for).
/// `complete` when the range's end was reached, else stopReason says where and why.
/// InputError without the problem's phase coefficients.
FollowedPeakCurve continuePeak(const PeakTrackingProblem& problem, const Eigen::VectorXd& x0, double w0,
                               const PeakContinuationOptions& options);

}  // namespace cyclone::continuation
