#pragma once
// The disc chain's plan and stages (private to the scenes library): what a disc scene
// asks for, read and checked before any FE work, and the stages that run it.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "SceneStages.hpp"
#include "cyclone/continuation/PeakFollowing.hpp"
#include "cyclone/disc/DiscForcedResponse.hpp"
#include "cyclone/disc/DiscHarmonicBalance.hpp"
#include "cyclone/disc/DiscPeakVibration.hpp"
#include "cyclone/disc/DiscReducedModels.hpp"
#include "cyclone/fatigue/GoodmanHaigh.hpp"

namespace cyclone::scenes {

using disc::DiscModelSpec;
using disc::DiscReducedModels;
using disc::DiscResponseSpec;
using disc::PeakPoint;

/// What `disc_response/peak_stress` asks for: the sector's whole vibration at the
/// friction-damped peak, its stresses and (margin) the Goodman-Haigh safety factor.
struct PeakStressSpec {
  bool run = false;
  bool margin = true;
  int animationSteps = 32;  ///< time steps of one period in disc_peak_vibration.exo
  double atHz = 0;          ///< 0: at the peak; else at this frequency of the reference curve
  fatigue::FatigueMaterial material;
  std::string stressUnit = "stress units";  ///< "MPa" or "Pa" from material/units (fe::stressUnitName)
};
/// Reads disc_response/peak_stress and material/fatigue (`material` as read). InputError
/// when a margin is asked for without fatigue data, naming both keys.
PeakStressSpec readPeakStressSpec(SceneSection& discResponse, SceneSection materialSection,
                                  const fe::IsotropicElastic& material);

/// The sector's vibration at the reference curve's peak (the harmonics check's highest
/// found level, else the traced point nearest the peak): disc_peak_response.exo (per
/// harmonic displacement, stresses, safety factor), disc_peak_vibration.exo (one period
/// as time steps), and with a margin disc_peak_stress.csv (every node, worst first) and
/// disc_goodman.svg; lines for the summary (the margin's after the headline's when
/// `afterHeadline`: the summary starts with the friction-damped peak).
void writePeakStress(const PeakStressSpec& spec, const mesh::Mesh& mesh, const DiscReducedModels& models,
                     const DiscModelSpec& modelSpec, const PeakPoint& point, double excitationScale,
                     bool afterHeadline, const std::string& outDir, linalg::CommPtr comm, SceneSummary& summary);

/// One peak study of disc_response/peak_studies: the parameter, its range and values.
struct DiscPlan;

struct PeakStudySpec {
  std::string name;  ///< preload, mu, contact_stiffness, force, loss_factor, clearance or speed
  double from = 0, to = 0;
  int values = 24;
  bool continuation = false;  ///< method: continuation (one LOCA continuation), else a peak search per value
};

/// Reads and checks disc_response/peak_studies before any work (InputError naming the
/// key: a range that is not 0 < from < to or does not contain the scene's value, values
/// outside 3..400, an unknown parameter).
std::vector<PeakStudySpec> readPeakStudies(SceneSection peakStudies, const DiscResponseSpec& spec, double lossFactor,
                                           double rpm);

/// disc_response/peak_studies (preload, mu, force): the largest peak followed over the
/// parameter by a peak search per value from the reference curve's peak; peak_<name>.csv
/// and .svg (the optimum marked, the value-list study's peaks beside it); lines for the
/// summary, with the largest difference from the study's peaks at shared values.
/// `listed`: per study name, the value-list study's curve tops (value, x, frequency, peak).
void followDiscPeaks(const std::vector<PeakStudySpec>& studies, const mesh::Mesh& mesh, const DiscReducedModels& models,
                     const DiscPlan& plan, const ForcedResponseSetup& reference,
                     const ForcedResponseResult& referenceResult, double bandFromHz, double bandToHz,
                     const std::map<std::string, std::vector<continuation::KnownPeak>>& listed,
                     const std::string& outDir,
                     linalg::CommPtr comm, SceneSummary& summary);

// What a disc scene asks for, read and checked before any FE work.
struct DiscPlan {
  DiscModelSpec modelSpec;   ///< with the check of the engine order's nodal diameter
  std::string cacheDir;      ///< empty: nothing cached
  std::vector<int> nds;      ///< the nodal diameters the models are built for
  DiscResponseSpec spec;
  int harmonicsCheckTo = 0;
  double harmonicsTolerance = 0;  ///< harmonics: auto's target (0: harmonics given)
  PeakStressSpec peakStress;
  std::vector<PeakStudySpec> peakStudies;
  bool rebuildCache = false;  ///< reduced_model/cache: rebuild (the cache emptied when the stage starts)
};

/// Reads and checks a disc scene's reduced_model and disc_response sections (r, d).
/// Without a forced response, reduced_model/nodal_diameters is required unless
/// `requireNodalDiameters` is false (a section checked that no analysis reads).
DiscPlan readDiscPlan(SceneSection& scene, SceneSection& r, SceneSection& d, const mesh::Mesh& mesh,
                      int builtInSectors, bool forcedResponse, const std::string& outDir,
                      bool requireNodalDiameters = true);
/// disc_response's sweep keys (family, range, stability, continuation) with the check's top H.
disc::DiscSweepOptions readSweepOptions(SceneSection& d, const DiscPlan& plan,
                                        const std::shared_ptr<continuation::TraceCheckpoints>& checkpoints);
/// disc_response's own keys: engine order, harmonics, samples, contact, gap, excitation and
/// response node sets (DiscResponseReaders.cpp).
DiscResponseSpec readDiscResponseSpec(SceneSection& d);
/// disc_response/hysteresis_contacts: the contact pairs whose loops are written.
std::vector<int> readHysteresisContacts(SceneSection& d, const mesh::Mesh& mesh, const DiscResponseSpec& spec);

/// disc_response/studies' parameters (one frequency curve per listed value).
inline constexpr const char* kStudyNames[] = {"preload", "mu", "contact_stiffness", "force",
                                              "loss_factor", "harmonics", "modes", "clearance"};

/// A study value that reproduces the reference scene: disc_frc's files under the study's
/// name `tag` (DiscStudies.cpp).
void copyReferenceCurve(const std::string& outDir, const std::string& tag, const std::string& what,
                        linalg::CommPtr comm, SceneSummary& summary);

/// Writes a disc curve with its summary lines (a range-end warning says where to widen
/// it; DiscStages.cpp).
void writeDiscCurve(const disc::DiscForcedResponse& solved, const ForcedResponseSetup& setup,
                    const ForcedResponseResult& result, const std::string& name, const std::vector<std::string>& warnings,
                    const std::string& outDir, linalg::CommPtr comm, SceneSummary& summary);

/// What disc_response/studies traced: the curves, and per study its curves' tops (those
/// with a peak) for the peak studies' comparison.
struct ValueStudies {
  int curves = 0;
  std::map<std::string, std::vector<continuation::KnownPeak>> tops;
};
/// disc_response/studies (DiscStudies.cpp): a frequency curve per listed value, each
/// study's plot and table.
ValueStudies valueStudiesStage(SceneSection studies, const mesh::Mesh& mesh, const DiscReducedModels& models,
                               const DiscPlan& plan, const disc::DiscForcedResponse& solved,
                               const disc::DiscSweepOptions& sweep, const std::string& outDir, linalg::CommPtr comm,
                               SceneSummary& summary);

/// Contacts, loops, the period and the sector's stresses at one point: the converged peak
/// (or peak_stress/at_hz for the stresses); DiscPeakStress.cpp.
void peakOutputsStage(const mesh::Mesh& mesh, const DiscReducedModels& models, const DiscPlan& plan,
                      disc::DiscForcedResponse& solved, const std::vector<int>& hysteresisContacts,
                      const std::string& outDir, linalg::CommPtr comm, SceneSummary& summary);

/// Everything the disc chain's stages take from the scene, read and checked before any
/// work (the keys of reduced_model, disc_response and its studies; node sets, ranges).
struct DiscStagePlan {
  DiscPlan plan;
  bool forcedResponse = false;
  std::optional<disc::DiscSweepOptions> sweep;  ///< with a forced response
  std::vector<int> hysteresisContacts;
  SceneSection studies;  ///< disc_response/studies: its values are read with their curves
};
DiscStagePlan readDiscStagePlan(SceneSection& scene, const mesh::Mesh& mesh, int builtInSectors, bool forcedResponse,
                                const std::string& outDir,
                                const std::shared_ptr<continuation::TraceCheckpoints>& checkpoints);

/// The disc chain's stages: reduced models per nodal diameter (cached), then the
/// forced response with friction at the shroud and its parameter studies.
/// Its curves save their traces in the plan's checkpoints as they go (none: not saved).
void discStages(const DiscStagePlan& stages, const mesh::Mesh& mesh, const std::string& outDir, linalg::CommPtr comm,
                SceneSummary& summary);

}  // namespace cyclone::scenes
