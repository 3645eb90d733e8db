// The trace's settings made into the library's setup, key by key as a scene's
// continuation and output keys are read (drivers/src/ForcedResponseScene.cpp).
#include "TraceSetup.hpp"

#include "Names.hpp"
#include "cyclone/core/Error.hpp"
#include "cyclone/hbm/HarmonicRefinement.hpp"

namespace cyclone::python {

using response::ForcedResponseSetup;

namespace {

// The tolerance and steps the caller gave, over the engine's own defaults.
void applySteps(const TraceOptions& o, continuation::ContinuationOptions& opt) {
  opt.tolerance = o.tolerance.value_or(opt.tolerance);
  opt.initialStep = o.initialStep.value_or(opt.initialStep);
  opt.minStep = o.minStep.value_or(opt.minStep);
  opt.maxStep = o.maxStep.value_or(opt.maxStep);
  opt.maxSteps = o.maxPoints.value_or(opt.maxSteps);
  opt.turnAngle = o.turnAngle.value_or(opt.turnAngle);
}

}  // namespace

ForcedResponseSetup setupOf(const hbm::HarmonicBalanceSystem& system, const TraceOptions& o) {
  ForcedResponseSetup setup;
  setup.system = hbm::withHarmonics(system, system.aft().harmonics(), system.aft().numSamples());
  setup.elementNames = o.elementNames;
  if (o.parameter != "omega") setup.omega = o.omega;
  if (o.parameter == "omega") {
    setup.parameter = ForcedResponseSetup::Parameter::Omega;
  } else if (o.parameter == "force_scale") {
    setup.parameter = ForcedResponseSetup::Parameter::ForceScale;
  } else if (o.parameter == "damping_scale") {
    setup.parameter = ForcedResponseSetup::Parameter::DampingScale;
  } else if (const auto slash = o.parameter.find('/'); slash != std::string::npos) {
    try {  // every element of that name, the law's parameter checked at the range's start
      response::selectElementParameter(setup, o.parameter.substr(0, slash), o.parameter.substr(slash + 1), o.start);
    } catch (const InputError& e) {
      throw InputError("parameter", e.problem());
    }
  } else {
    throw InputError("parameter", "'" + o.parameter + "': must be omega, force_scale, damping_scale or "
                                  "<element name>/<parameter> (e.g. contact/preload)");
  }
  setup.excitationScale = o.forceScale;
  auto& opt = setup.continuation;
  if (o.engine.empty()) {
    setup.fallback = continuation::locaOptions();
  } else if (o.engine == "loca") {
    opt = continuation::locaOptions();
  } else if (o.engine != "predictor_corrector") {
    throw InputError("engine", "'" + o.engine + "': must be predictor_corrector or loca");
  }
  opt.from = o.start, opt.to = o.end;
  applySteps(o, opt);
  setup.outputDofs = o.outputDofs;
  for (int d = 0; d < system.numDofs(); ++d) setup.dofNames.push_back("dof" + std::to_string(d));
  setup.stability = stabilityFromName(o.stability);
  setup.harmonicsCheckTo = o.harmonicsCheckTo;
  return setup;
}

void applyDiscContinuation(const TraceOptions& o, disc::DiscSweepOptions& sweep) {
  using Engine = continuation::ContinuationOptions::Engine;
  if (!o.engine.empty()) {
    if (o.engine != "loca" && o.engine != "predictor_corrector")
      throw InputError("engine", "'" + o.engine + "': must be predictor_corrector or loca");
    sweep.continuation = disc::discContinuationOptions(o.engine == "loca" ? Engine::Loca : Engine::PredictorCorrector);
    sweep.fallback.reset();
  }
  applySteps(o, sweep.continuation);
}

}  // namespace cyclone::python
