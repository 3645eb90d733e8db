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
  double excitationScale = 1;  ///< Omega: the scale s of f = s f_ex (excitation: scale); static loads stay
  continuation::ContinuationOptions continuation;
  std::vector<int> outputDofs;
};

/// The continuation problem of a harmonic balance system in the chosen parameter:
/// the frequency, or the excitation scale at the fixed frequency `omega`.
continuation::ContinuationProblem continuationProblem(const hbm::HarmonicBalanceSystem& system,
                                                      ForcedResponseSetup::Parameter parameter, double omega = 0,
                                                      double excitationScale = 1.0);

/// Reads the keys of a forced-response scene (strictly: unknown keys are errors).
ForcedResponseSetup readForcedResponseSetup(SceneSection& scene);
/// The same from a scene file.
ForcedResponseSetup loadForcedResponseScene(const std::string& path);

}  // namespace cyclone::scenes
