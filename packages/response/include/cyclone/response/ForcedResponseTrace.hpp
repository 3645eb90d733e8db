#pragma once
// The first point of a forced-response curve and the curve itself over the problem's
// range, by the continuation engines with their fallbacks (a second sweep from the
// range's end, the other engine).
#include <string>

#include <Eigen/Dense>

#include "cyclone/continuation/ArclengthContinuation.hpp"
#include "cyclone/response/ForcedResponseSetup.hpp"

namespace cyclone::response {

/// A converged harmonic balance solution at the start of a scene's range, and how it was found.
struct StartingPoint {
  Eigen::VectorXd x;   ///< empty when no way converged
  std::string method;  ///< what converged (or why nothing did)
  double seconds = 0;
};

/// The first point of a forced-response curve at the start of the range (the frequency
/// `continuation.from`, or the scale `continuation.from` at `omega`), tried in this order:
///  1. Newton with line search from rest, X = 0: its first step solves the system
///     linearised at rest (friction elements stuck, open gaps and cubic springs without
///     stiffness; NLvib's start for its example 07);
///  2. the same from the linear solution without the nonlinear elements;
///  3. from H >= 4, the first harmonics' solution carried up level by level (Newton, or a
///     homotopy to the added harmonics where Newton stalls), corrected by Newton;
///  4. a ramp of the excitation scale from 0 (the system at rest) to the start's scale
///     at the start frequency by arclength continuation (through folds in the scale),
///     its end corrected by Newton.
/// Each Newton attempt stops at a stagnation (continuation::solveNewton), so a failed way
/// costs a few iterations.
StartingPoint findStartingPoint(ForcedResponseSetup& setup);

constexpr double kLogForceDecadeRatio = 100;

/// The curve a scene describes: arclength continuation over the range from a
/// starting point (by default findStartingPoint's). Without one (an empty x) the curve
/// is traced from the end of the range towards its start, as far as a start found
/// there allows; the stop reason says why the start failed and how far the sweep got.
/// A sweep that does not reach the end of the range
/// (it returned to its start, or stopped with a reason) is followed by a second sweep
/// from the range's end, a second segment of the branch (Branch::segmentStarts); the
/// stop reason says how far each got. The scene runner and the tests both trace here.
/// A force-scale curve whose range spans more than kLogForceDecadeRatio (both ends positive)
/// is traced in q = ln s with the response per unit force X / s as unknowns and the
/// residual relative to the force at s; its points are given back in s and X.
continuation::Branch traceForcedResponse(ForcedResponseSetup& setup, const StartingPoint& start);
continuation::Branch traceForcedResponse(ForcedResponseSetup& setup);

}  // namespace cyclone::response
