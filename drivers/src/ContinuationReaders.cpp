// A continuation section's engine, steps and tolerance, read onto
// continuation::ContinuationOptions: the matrix scene's and the disc's continuation keys.
#include <string>
#include <utility>

#include "cyclone/continuation/ArclengthContinuation.hpp"
#include "cyclone/core/Error.hpp"
#include "cyclone/core/NumberText.hpp"
#include "cyclone/scenes/ForcedResponseScene.hpp"
#include "cyclone/scenes/SceneSection.hpp"

namespace cyclone::scenes {

double readContinuationTolerance(SceneSection& cs, double defaultValue) {
  const double tolerance = cs.getDouble("tolerance", defaultValue);
  if (!(tolerance >= 1e-14 && tolerance <= 1e-4))
    throw InputError(cs.where("tolerance"), numberText(tolerance) +
                                                ": must lie in 1e-14..1e-4, the residual relative to the forces acting "
                                                "(below: under the rounding of double precision; above: a response "
                                                "near a resonance, amplified by its quality factor, off by percents)");
  return tolerance;
}

void readContinuationSteps(SceneSection& cs, continuation::ContinuationOptions& opt, const std::string& defaultEngine) {
  using Options = continuation::ContinuationOptions;
  const std::string engine = cs.getString("engine", defaultEngine);
  const auto chosen = continuation::engineFromKey(engine);
  if (!chosen)
    throw InputError(cs.where("engine"), "'" + engine + "': must be " +
                                             continuation::engineKey(Options::Engine::PredictorCorrector) + " or " +
                                             continuation::engineKey(Options::Engine::Loca));
  if (*chosen == Options::Engine::Loca && opt.engine != Options::Engine::Loca) {
    const Options loca = continuation::locaOptions();  // LOCA's step defaults, its units
    opt.initialStep = loca.initialStep, opt.minStep = loca.minStep, opt.maxStep = loca.maxStep;
  }
  opt.engine = *chosen;
  opt.initialStep = cs.getDouble("initial_step", opt.initialStep);  // the caller's defaults
  opt.minStep = cs.getDouble("min_step", opt.minStep);
  opt.maxStep = cs.getDouble("max_step", opt.maxStep);
  opt.maxSteps = cs.getInt("max_points", opt.maxSteps);
  opt.turnAngle = cs.getDouble("turn_angle", opt.turnAngle);
  if (!(opt.initialStep > 0)) throw InputError(cs.where("initial_step"), "must be positive");
  if (!(opt.minStep > 0)) throw InputError(cs.where("min_step"), "must be positive");
  if (!(opt.maxStep >= opt.minStep)) throw InputError(cs.where("max_step"), "must be at least min_step");
  // The predictor-corrector's steps are in the scaled space (x / |x|, p / |to - from|),
  // where 1 spans the whole range: a longer step means nothing (issue 49: 1000).
  if (opt.engine == Options::Engine::PredictorCorrector)
    for (const auto& [key, value] : {std::pair<const char*, double>{"initial_step", opt.initialStep},
                                     {"max_step", opt.maxStep}})
      if (value > 1)
        throw InputError(cs.where(key), numberText(value) + ": must be at most 1 (the steps are in the scaled "
                                        "space x / |x|, p / |to - from|, where 1 spans the whole range)");
  if (opt.maxSteps < 2) throw InputError(cs.where("max_points"), "must be at least 2");
  if (!(opt.turnAngle > 0 && opt.turnAngle < 1.5))
    throw InputError(cs.where("turn_angle"), "must lie in (0, 1.5) radians");
  using LS = Options::LineSearch;
  opt.lineSearch = cs.getChoice<LS>(
      "line_search", "full_step", {{"full_step", LS::FullStep}, {"backtrack", LS::Backtrack}, {"polynomial", LS::Polynomial}},
      [](const std::string& word) { return "'" + word + "': must be full_step, backtrack or polynomial"; });
  if (cs.has("line_search") && opt.engine != Options::Engine::Loca)
    throw InputError(cs.where("line_search"), "is for engine: loca (the predictor-corrector backtracks by itself)");
}

}  // namespace cyclone::scenes
