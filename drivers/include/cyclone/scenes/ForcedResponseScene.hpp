#pragma once
// The forced-response part of a scene (system, nonlinear elements, excitation,
// harmonics, samples, continuation, output) read into the problem the library traces
// (response/ForcedResponseSetup.hpp), so tests and codes can rebuild exactly the
// system a scene describes.
#include <string>

#include "cyclone/continuation/ArclengthContinuation.hpp"
#include "cyclone/response/ForcedResponseSetup.hpp"

namespace cyclone::scenes {

class SceneSection;

/// The continuation section's engine and step keys (engine: loca or predictor_corrector,
/// `defaultEngine` when not given; initial_step, min_step, max_step, max_points,
/// turn_angle; for loca line_search: full_step, backtrack or polynomial), defaults the
/// values in `options` on entry; a value out of its domain is an InputError naming the key.
void readContinuationSteps(SceneSection& continuationSection, continuation::ContinuationOptions& options,
                           const std::string& defaultEngine);
/// continuation/tolerance: the Newton residual relative to the forces acting, within
/// [1e-14, 1e-4] (InputError with the key): below, double precision's rounding of these
/// systems; above, a response near a resonance, amplified by its quality factor (hundreds),
/// off by percents (0.99 moved the disc's peak by 23 % while the harmonics took the blame).
double readContinuationTolerance(SceneSection& continuationSection, double defaultValue);

/// Reads the keys of a forced-response scene (strictly: unknown keys are errors).
response::ForcedResponseSetup readForcedResponseSetup(SceneSection& scene);
/// The same from a scene file.
response::ForcedResponseSetup loadForcedResponseScene(const std::string& path);

}  // namespace cyclone::scenes
