#pragma once
// A parameter study of a disc's friction-damped response: one frequency curve per
// value of a contact, excitation or model parameter, over the reference curve's range,
// with its peak. A value that reproduces the reference scene is the reference curve.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "cyclone/disc/DiscForcedResponse.hpp"

namespace cyclone::disc {

enum class DiscStudyParameter {
  Preload,              ///< N0 of every shroud contact
  FrictionCoefficient,  ///< mu
  ContactStiffness,     ///< kn and kt together
  Force,                ///< a factor on the excitation amplitude
  Clearance,            ///< the gap elements' clearance (needs gap pairs)
  Harmonics,            ///< H: harmonics 0..H (the models must hold their nodal diameters)
  LossFactor,           ///< the reduced models' structural damping (hybrid and truncation models)
  Modes,                ///< the reduced models' kept natural frequencies (hybrid and truncation models)
  Speed,                ///< the rotational speed (rpm) the reduced models are built at (peak following only)
};
/// preload, mu, contact_stiffness, force, clearance, harmonics, loss_factor, modes, speed.
std::string discStudyParameterName(DiscStudyParameter parameter);
/// The parameter of a name (none for another name).
std::optional<DiscStudyParameter> discStudyParameterFromName(const std::string& name);

struct DiscStudyCurve {
  double value = 0;
  bool isReference = false;  ///< the value reproduces the reference: its curve, not traced again
  response::ForcedResponseResult curve;
  std::vector<std::string> warnings;  ///< e.g. the largest response at the end of the sweep
  double seconds = 0;
};

/// Called after each curve with the setup it was traced with (the reference's for a
/// reference value), e.g. to write it while the study goes on.
using DiscStudyVisitor = std::function<void(const DiscStudyCurve& curve, const response::ForcedResponseSetup& setup)>;

/// The curves of `parameter` at `values`, each over reference.fromHz..toHz with
/// `options` (the harmonics check off: a study's error is the reference's). InputError
/// (naming disc_response/studies/<name>) for a value the models or elements cannot take.
std::vector<DiscStudyCurve> studyDisc(const mesh::Mesh& mesh, const DiscReducedModels& models,
                                      const DiscResponseSpec& spec, const DiscForcedResponse& reference,
                                      DiscStudyParameter parameter, const std::vector<double>& values,
                                      const DiscSweepOptions& options, const DiscStudyVisitor& visit = {});

/// Every value of a study checked before any work (InputError naming
/// disc_response/studies/<name> and the value): the contact and excitation values as
/// checkDiscResponse checks the spec's, a loss factor >= 0, modes from 1 to the models'
/// `modes`, harmonics from 1 to `maxHarmonic` (the highest the models are built for).
void checkDiscStudyValues(const mesh::Mesh& mesh, int sectors, const mesh::RotationAxis& axis,
                          const DiscResponseSpec& spec, DiscStudyParameter parameter, const std::vector<double>& values,
                          int modes, int maxHarmonic, double youngsModulus);

/// The models with another loss factor (>= 0) or fewer modes (> 0; else kept): hybrid and
/// truncation models only (InputError otherwise).
DiscReducedModels variedModels(const DiscReducedModels& base, double lossFactor, int modes);

}  // namespace cyclone::disc
