#pragma once
// The forced-response part of a scene (system, nonlinear elements, excitation,
// harmonics, samples, continuation, output) read into the objects that trace
// it, so tests and codes can rebuild exactly the system a scene describes.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cyclone/continuation/ArclengthContinuation.hpp"
#include "cyclone/continuation/PeakTracking.hpp"
#include "cyclone/hbm/HarmonicBalanceSystem.hpp"

namespace cyclone::scenes {

class SceneSection;

struct ForcedResponseSetup {
  std::unique_ptr<hbm::HarmonicBalanceSystem> system;
  /// The continuation parameter: the excitation frequency (rad/s); the excitation
  /// scale s (f = s f_ex); a parameter of one nonlinear element (e.g. a contact's
  /// preload, kn, kt, mu); or a scale of the damping. All but Omega at the fixed
  /// frequency `omega`.
  enum class Parameter { Omega, ForceScale, ElementParameter, DampingScale } parameter = Parameter::Omega;
  double omega = 0;            ///< the fixed excitation frequency unless the parameter is Omega
  /// Omega: omega = p x omegaUnit, so the continuation runs on a parameter of order one
  /// (e.g. the frequency over a reference frequency for an FE disc, whose omega is ~1e4 rad/s).
  double omegaUnit = 1;
  /// The continuation works on X / unknownScale (0: the first point's largest coefficient),
  /// so that unknowns of order one meet a parameter of order one in LOCA's arclength.
  double unknownScale = 1;
  double excitationScale = 1;  ///< the scale s of f = s f_ex (excitation: scale) unless the parameter is ForceScale
  std::vector<std::string> elementNames;  ///< the scene's names of system->elements(), in order
  /// ElementParameter: which elements (all elements of one name, e.g. every shroud contact)
  std::vector<int> parameterElements;
  std::string elementParameter;  ///< ElementParameter: which of their parameters
  std::vector<std::shared_ptr<const hbm::NonlinearElement>> baseElements;  ///< ElementParameter: as the scene gives them
  continuation::ContinuationOptions continuation;
  /// Where `continuation` leaves the curve incomplete, traceForcedResponse traces it
  /// again with these options (another engine; the range and tolerance are continuation's).
  std::optional<continuation::ContinuationOptions> fallback;
  std::vector<int> outputDofs;
  std::vector<std::string> dofNames;  ///< system: dof_names, or dof0, dof1, ...
  std::string stability = "auto";  ///< Hill's method per point: auto (small systems), true, false
  /// The harmonics check of a frequency curve finds the peak with H, H + 1, ... up to this
  /// (0: H + 1), each level by a peak search from the one before; < 0: no harmonics check.
  int harmonicsCheckTo = 0;
  /// The scene key that sets the harmonics, for the message when the harmonic balance
  /// would not fit in memory.
  std::string harmonicsKey = "harmonics";
  /// A curve of which no point was computed: the run fails with the reason and writes
  /// none of its files (the scene's curve), or the curve is reported empty and the run
  /// goes on (one curve of a parameter study, whose table says so).
  enum class WhenNothingTraced { Fail, Report } whenNothingTraced = WhenNothingTraced::Fail;
  /// What the scene's reading found worth saying (e.g. how an engine order folds onto a
  /// nodal diameter); the run's summary lists them.
  std::vector<std::string> notes;

  /// The parameter's name for outputs: omega, force_scale, <element>/<parameter>, damping_scale.
  std::string parameterName() const;
  /// Puts the system at parameter value p (swaps the element or sets the damping
  /// scale) and returns the frequency and excitation scale that go with it.
  std::pair<double, double> apply(double p);
};

/// Makes the continuation parameter `parameter` (e.g. preload) of every element named
/// `element` (InputError if none, or if `probe` is not a valid value of it).
void selectElementParameter(ForcedResponseSetup& setup, const std::string& element, const std::string& parameter,
                            double probe);

/// The continuation problem of a scene's system in its parameter (the closures
/// keep a reference to `setup` and call setup.apply(p)).
continuation::ContinuationProblem continuationProblem(ForcedResponseSetup& setup);

/// The continuation problem of a harmonic balance system in the chosen parameter:
/// the frequency, or the excitation scale at the fixed frequency `omega`.
continuation::ContinuationProblem continuationProblem(const hbm::HarmonicBalanceSystem& system,
                                                      ForcedResponseSetup::Parameter parameter, double omega = 0,
                                                      double excitationScale = 1.0);

/// The scene's system with the frequency (rad/s) and its parameter (setup.parameter:
/// an element parameter, the damping or the force scale) as separate arguments, the
/// rows scaled as continuationProblem's; the measure is the first output DOF's
/// max |x(t)|. For continuation::followPeak (the closures keep a reference to `setup`).
continuation::PeakTrackingProblem peakFollowingProblem(ForcedResponseSetup& setup);

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
/// Each Newton attempt stops at a stagnation (continuation::solveNewton), so a failed way
/// costs a few iterations.
StartingPoint findStartingPoint(ForcedResponseSetup& setup);

/// The curve a scene describes: arclength continuation over the range from a
/// starting point (by default findStartingPoint's). Without one (an empty x) the curve
/// is traced from the end of the range towards its start, as far as a start found
/// there allows; the stop reason says why the start failed and how far the sweep got.
/// A sweep that does not reach the end of the range
/// (it returned to its start, or stopped with a reason) is followed by a second sweep
/// from the range's end, a second segment of the branch (Branch::segmentStarts); the
/// stop reason says how far each got. The scene runner and the tests both trace here.
continuation::Branch traceForcedResponse(ForcedResponseSetup& setup, const StartingPoint& start);
continuation::Branch traceForcedResponse(ForcedResponseSetup& setup);

/// The continuation section's engine and step keys (engine: loca or predictor_corrector,
/// `defaultEngine` when not given; initial_step, min_step, max_step, max_points,
/// turn_angle; for loca line_search: full_step, backtrack or polynomial), defaults the
/// values in `options` on entry; a value out of its domain is an InputError naming the key.
void readContinuationSteps(SceneSection& continuationSection, continuation::ContinuationOptions& options,
                           const std::string& defaultEngine);

/// Reads the keys of a forced-response scene (strictly: unknown keys are errors).
ForcedResponseSetup readForcedResponseSetup(SceneSection& scene);
/// The same from a scene file.
ForcedResponseSetup loadForcedResponseScene(const std::string& path);

}  // namespace cyclone::scenes
