#include "cyclone/disc/DiscParameterStudy.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

#include "cyclone/core/Error.hpp"
#include "cyclone/core/Log.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/rom/HybridFrfModel.hpp"

namespace cyclone::disc {

namespace {

constexpr DiscStudyParameter kParameters[] = {
    DiscStudyParameter::Preload, DiscStudyParameter::FrictionCoefficient, DiscStudyParameter::ContactStiffness,
    DiscStudyParameter::Force,   DiscStudyParameter::Clearance,           DiscStudyParameter::Harmonics,
    DiscStudyParameter::LossFactor, DiscStudyParameter::Modes,            DiscStudyParameter::Speed};

// The spec at one value of a contact or excitation parameter (the elements' values, no
// models needed), and whether it reproduces the reference; none for the other parameters.
std::optional<std::pair<DiscResponseSpec, bool>> specWithElementValue(const DiscResponseSpec& spec,
                                                                      DiscStudyParameter parameter, double v,
                                                                      const std::string& key) {
  DiscResponseSpec sv = spec;
  switch (parameter) {
    case DiscStudyParameter::Preload: sv.contact.preload = v; return std::pair{sv, v == spec.contact.preload};
    case DiscStudyParameter::FrictionCoefficient: sv.contact.mu = v; return std::pair{sv, v == spec.contact.mu};
    case DiscStudyParameter::ContactStiffness:
      sv.contact.kn = v, sv.contact.kt = v;
      return std::pair{sv, v == spec.contact.kn && v == spec.contact.kt};
    case DiscStudyParameter::Force:
      sv.excitation.amplitude = spec.excitation.amplitude * v;
      return std::pair{sv, v == 1.0};
    case DiscStudyParameter::Clearance:
      if (spec.gap.pairs.empty()) throw InputError(key, "needs gap elements (disc_response/gap/pairs)");
      sv.gap.clearance = v;
      return std::pair{sv, v == spec.gap.clearance};
    default: return std::nullopt;
  }
}

// The spec at one value, and whether it reproduces the reference (the loss factor and
// modes change the models: never the reference).
std::pair<DiscResponseSpec, bool> specAt(const DiscResponseSpec& spec, DiscStudyParameter parameter, double v,
                                         const DiscReducedModels& models, int sectors, const std::string& key) {
  if (auto element = specWithElementValue(spec, parameter, v, key)) return *element;
  DiscResponseSpec sv = spec;
  switch (parameter) {
    case DiscStudyParameter::Harmonics:
      sv.harmonics.clear();
      for (int h = 0; h <= int(v); ++h) sv.harmonics.push_back(h);
      for (int k : nodalDiametersFor(sectors, spec.engineOrder, sv.harmonics))
        if (!models.models.count(k))
          throw InputError(key, "harmonic " + std::to_string(int(v)) + " needs nodal diameter " + std::to_string(k) +
                                    ": raise disc_response/harmonics to the study's largest value");
      return {sv, sv.harmonics == spec.harmonics};
    case DiscStudyParameter::LossFactor:
    case DiscStudyParameter::Modes: return {sv, false};
    case DiscStudyParameter::Speed:
      throw InputError(key, "the speed is followed (peak_studies: speed: the models built at each speed), not "
                            "swept as a value list");
    default: break;  // the elements' values, above
  }
  return {sv, false};
}

}  // namespace

std::string discStudyParameterName(DiscStudyParameter parameter) {
  switch (parameter) {
    case DiscStudyParameter::Preload: return "preload";
    case DiscStudyParameter::FrictionCoefficient: return "mu";
    case DiscStudyParameter::ContactStiffness: return "contact_stiffness";
    case DiscStudyParameter::Force: return "force";
    case DiscStudyParameter::Clearance: return "clearance";
    case DiscStudyParameter::Harmonics: return "harmonics";
    case DiscStudyParameter::LossFactor: return "loss_factor";
    case DiscStudyParameter::Modes: return "modes";
    case DiscStudyParameter::Speed: return "speed";
  }
  return "";
}

std::optional<DiscStudyParameter> discStudyParameterFromName(const std::string& name) {
  for (auto p : kParameters)
    if (discStudyParameterName(p) == name) return p;
  return std::nullopt;
}

void checkDiscStudyValues(const mesh::Mesh& mesh, int sectors, const mesh::RotationAxis& axis,
                          const DiscResponseSpec& spec, DiscStudyParameter parameter, const std::vector<double>& values,
                          int modes, int maxHarmonic, double youngsModulus) {
  const std::string key = "disc_response/studies/" + discStudyParameterName(parameter);
  if (values.empty()) throw InputError(key, "needs a list of values");
  auto at = [](double v) {
    std::ostringstream text;
    text << "the value " << v << ": ";
    return text.str();
  };
  for (double v : values) {
    if (!std::isfinite(v)) throw InputError(key, at(v) + "must be finite");
    switch (parameter) {
      case DiscStudyParameter::LossFactor:
        if (v < 0 || v > 1) throw InputError(key, at(v) + "a loss factor must lie in 0..1");
        break;
      case DiscStudyParameter::Modes:
        if (v != std::floor(v) || v < 1 || v > modes)
          throw InputError(key, at(v) + "must be a whole number of modes from 1 to the reduced models' " +
                                    std::to_string(modes) + " (reduced_model/modes)");
        break;
      case DiscStudyParameter::Harmonics:
        if (v != std::floor(v) || v < 1 || v > maxHarmonic)
          throw InputError(key, at(v) + "must be a whole number from 1 to " + std::to_string(maxHarmonic) +
                                    " (the highest harmonic the reduced models are built for: raise "
                                    "disc_response/harmonics to the study's largest value)");
        break;
      case DiscStudyParameter::Speed:
        throw InputError(key, "the speed is followed (peak_studies: speed: the models built at each speed), not "
                              "swept as a value list");
      default: {
        // The contact and excitation values as the spec's own are checked.
        const auto sv = specWithElementValue(spec, parameter, v, key)->first;
        try {
          checkDiscResponse(mesh, sectors, axis, sv, youngsModulus);
        } catch (const InputError& e) {
          throw InputError(key, at(v) + e.where() + ": " + e.problem());
        }
      }
    }
  }
}

DiscReducedModels variedModels(const DiscReducedModels& base, double lossFactor, int modes) {
  DiscReducedModels out = base;
  for (auto& [k, m] : out.models) {
    const auto* h = dynamic_cast<const rom::HybridFrfModel*>(m.get());
    if (!h) throw InputError("disc_response/studies", "loss_factor and modes studies need hybrid or truncation models");
    const double eta = lossFactor >= 0 ? lossFactor : h->lossFactor();
    const auto kept = modes > 0 ? h->modes().first(std::min(modes, h->modes().numModes() / h->modes().copies))
                                : h->modes();
    m = h->hasStaticCorrection() ? std::make_shared<rom::HybridFrfModel>(kept, h->staticCompliance(), eta)
                                 : std::make_shared<rom::HybridFrfModel>(rom::HybridFrfModel::modalTruncation(kept, eta));
  }
  return out;
}

std::vector<DiscStudyCurve> studyDisc(const mesh::Mesh& mesh, const DiscReducedModels& models,
                                      const DiscResponseSpec& spec, const DiscForcedResponse& reference,
                                      DiscStudyParameter parameter, const std::vector<double>& values,
                                      const DiscSweepOptions& options, const DiscStudyVisitor& visit) {
  const std::string name = discStudyParameterName(parameter), key = "disc_response/studies/" + name;
  if (values.empty()) throw InputError(key, "needs a list of values");
  DiscSweepOptions sweep = options;
  sweep.harmonicsCheckTo = -1;
  std::vector<DiscStudyCurve> curves;
  for (double v : values) {
    Timer timer;
    DiscStudyCurve c;
    c.value = v;
    const auto [sv, isReference] = specAt(spec, parameter, v, models, models.sectors, key);
    c.isReference = isReference;
    if (isReference) {
      c.curve = reference.curve;
      c.warnings = reference.warnings;
      log::info("study " + name + " = " + std::to_string(v) + ": the reference curve");
      if (visit) visit(c, reference.setup);
    } else {
      const DiscReducedModels varied =
          parameter == DiscStudyParameter::LossFactor ? variedModels(models, v, 0)
          : parameter == DiscStudyParameter::Modes    ? variedModels(models, -1, int(v))
                                                      : DiscReducedModels{};
      const bool usesVaried = parameter == DiscStudyParameter::LossFactor || parameter == DiscStudyParameter::Modes;
      auto setup = makeDiscForcedResponse(mesh, usesVaried ? varied : models, sv);
      c.curve = sweepDisc(setup, reference.fromHz, reference.toHz, sweep, c.warnings);
      if (c.curve.branch.points.empty())
        log::warn("study " + name + " = " + std::to_string(v) + ": no point of the curve was computed: " +
                  c.curve.branch.stopReason);
      c.seconds = timer.seconds();
      if (visit) visit(c, setup);
    }
    curves.push_back(std::move(c));
  }
  return curves;
}

}  // namespace cyclone::disc
