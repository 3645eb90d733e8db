#pragma once
// A forced-response problem: a harmonic balance system, the parameter it is traced in
// (frequency, excitation scale, a nonlinear element's parameter, damping scale), the
// range and continuation settings and the outputs, as the library traces it
// (ForcedResponse.hpp) and a scene describes it (scenes/ForcedResponseScene.hpp).
#include <cmath>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "cyclone/continuation/ArclengthContinuation.hpp"
#include "cyclone/continuation/PeakTracking.hpp"
#include "cyclone/hbm/HarmonicBalanceSystem.hpp"

namespace cyclone::response {

struct ForcedResponseSetup {
  std::unique_ptr<hbm::HarmonicBalanceSystem> system;
  /// The continuation parameter: the excitation frequency (rad/s); the excitation
  /// scale s (f = s f_ex); a parameter of one nonlinear element (e.g. a contact's
  /// preload, kn, kt, mu); a scale of the damping; or a parameter of the model itself
  /// (Rebuilt: `rebuild` makes the system at each value, e.g. a reduced model's loss
  /// factor, which lives inside its receptance). All but Omega at the fixed frequency `omega`.
  enum class Parameter { Omega, ForceScale, ElementParameter, DampingScale, Rebuilt } parameter = Parameter::Omega;
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
  /// ElementParameter: element i gets parameterWeights[i] p (empty: p each); e.g. a
  /// total normal load spread over contacts by their areas.
  std::vector<double> parameterWeights;
  /// Rebuilt: the system at a value (called when apply() gets a value other than the last
  /// one: a parameter study evaluates one value at a time), and the parameter's name.
  std::function<std::unique_ptr<hbm::HarmonicBalanceSystem>(double)> rebuild;
  std::string rebuiltParameter;
  double rebuiltAt = std::nan("");  ///< the value `system` was last rebuilt at
  continuation::ContinuationOptions continuation;
  /// Where `continuation` leaves the curve incomplete, traceForcedResponse traces it
  /// again with these options (another engine; the range and tolerance are continuation's).
  std::optional<continuation::ContinuationOptions> fallback;
  std::vector<int> outputDofs;
  std::vector<std::string> dofNames;  ///< system: dof_names, or dof0, dof1, ...
  /// Hill's method per point: Auto (a system small enough, and the whole curve's Hill's
  /// method, timed on its first point, within 3 times the trace's own time or 60 s; else
  /// not computed, said in stabilityNote), Always, Never.
  enum class Stability { Auto, Always, Never } stability = Stability::Auto;
  /// The harmonics check of a frequency curve finds the peak with H, H + 1, ... up to this
  /// (0: H + 1), each level by a peak search from the one before; < 0: no harmonics check.
  int harmonicsCheckTo = 0;
  /// Harmonics by an error target (> 0; 0: off): the harmonics check stops at the first
  /// level whose last two raises each changed the peak by at most this (relative; two,
  /// because a symmetric nonlinearity leaves every other harmonic at zero), and the curve
  /// is traced again, whole, with that level's harmonics (`system` becomes it). Frequency
  /// curves only; a check that does not get there leaves the curve as traced, an estimate.
  double harmonicsTolerance = 0;
  /// The scene key that sets the harmonics, for the message when the harmonic balance
  /// would not fit in memory.
  std::string harmonicsKey = "harmonics";
  /// The scene key that sets the harmonics check's highest level (harmonics_check_to, or
  /// harmonics_max for harmonics by an error target), for the messages of its cost.
  std::string harmonicsCheckKey = "harmonics_check_to";
  /// What the scene's reading found worth saying (e.g. how an engine order folds onto a
  /// nodal diameter); the run's summary lists them.
  std::vector<std::string> notes;

  /// The parameter's name for outputs: omega, force_scale, <element>/<parameter>, damping_scale,
  /// or rebuiltParameter.
  std::string parameterName() const;
  /// Puts the system at parameter value p (swaps the element, sets the damping scale or
  /// rebuilds the system) and returns the frequency and excitation scale that go with it.
  std::pair<double, double> apply(double p);
};

/// Makes the continuation parameter `parameter` (e.g. preload) of every element named
/// `element`, each element taking weights[i] p (empty: p; InputError if no element has
/// that name, the weights are not one per such element, or `probe` is not a valid value).
void selectElementParameter(ForcedResponseSetup& setup, const std::string& element, const std::string& parameter,
                            double probe, std::vector<double> weights = {});

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

}  // namespace cyclone::response
