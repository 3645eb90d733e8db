#pragma once
// The forced-response part of a scene (system, nonlinear elements, excitation,
// harmonics, samples, continuation, output) read into the objects that trace
// it, so tests and codes can rebuild exactly the system a scene describes.
#include <memory>
#include <string>
#include <vector>

#include "cyclone/continuation/ArclengthContinuation.hpp"
#include "cyclone/hbm/HarmonicBalanceSystem.hpp"

namespace cyclone::scenes {

class SceneSection;

struct ForcedResponseSetup {
  std::unique_ptr<hbm::HarmonicBalanceSystem> system;
  /// The continuation parameter: the excitation frequency (rad/s), or the excitation
  /// scale s (f = s f_ex) at the fixed frequency `omega`.
  enum class Parameter { Omega, ForceScale } parameter = Parameter::Omega;
  double omega = 0;  ///< ForceScale: the fixed excitation frequency
  continuation::ContinuationOptions continuation;
  std::vector<int> outputDofs;
};

/// The continuation problem of a harmonic balance system in the chosen parameter:
/// the frequency, or the excitation scale at the fixed frequency `omega`.
continuation::ContinuationProblem continuationProblem(const hbm::HarmonicBalanceSystem& system,
                                                      ForcedResponseSetup::Parameter parameter, double omega = 0);

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
///  3. a ramp of the excitation scale from 0 (the system at rest) to the start's scale
///     at the start frequency by arclength continuation (through folds in the scale),
///     its end corrected by Newton.
/// Each Newton attempt stops at a stagnation (continuation::solveAt), so a failed way
/// costs a few iterations.
StartingPoint findStartingPoint(const ForcedResponseSetup& setup);

/// The curve a scene describes: arclength continuation over the range from a
/// starting point (by default findStartingPoint's; an empty one gives an empty branch
/// whose stop reason is its method). The scene runner and the tests both trace here.
continuation::Branch traceForcedResponse(const ForcedResponseSetup& setup, const StartingPoint& start);
continuation::Branch traceForcedResponse(const ForcedResponseSetup& setup);

/// Reads the keys of a forced-response scene (strictly: unknown keys are errors).
ForcedResponseSetup readForcedResponseSetup(SceneSection& scene);
/// The same from a scene file.
ForcedResponseSetup loadForcedResponseScene(const std::string& path);

}  // namespace cyclone::scenes
