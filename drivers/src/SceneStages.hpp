#pragma once
// What the scene runner's stages share (private to the scenes library).
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "cyclone/analysis/StaticAnalysis.hpp"
#include "cyclone/continuation/ArclengthContinuation.hpp"
#include "cyclone/cyclic/CyclicSector.hpp"
#include "cyclone/cyclic/ModalSweep.hpp"
#include "cyclone/scenes/SceneSection.hpp"
#include "cyclone/fatigue/GoodmanHaigh.hpp"
#include "cyclone/hbm/HarmonicBalanceSystem.hpp"
#include "cyclone/fe/LinearAlgebra.hpp"
#include "cyclone/fe/Material.hpp"
#include "cyclone/disc/DiscForcedResponse.hpp"
#include "cyclone/disc/DiscHarmonicBalance.hpp"
#include "cyclone/disc/DiscPeakVibration.hpp"
#include "cyclone/disc/DiscReducedModels.hpp"
#include "cyclone/response/ForcedResponse.hpp"
#include "cyclone/scenes/ForcedResponseScene.hpp"
#include "cyclone/scenes/SceneRunner.hpp"

namespace cyclone::mesh {
class Mesh;
}
namespace cyclone::io {
class TraceCheckpointDirectory;
}

namespace cyclone::scenes {

class SceneSection;
using response::ForcedResponseResult;
using response::ForcedResponseSetup;
using disc::DiscModelSpec;
using disc::DiscReducedModels;
using disc::DiscResponseSpec;
using disc::PeakPoint;

class RunManifest;

/// The mesh stage (MeshStage.cpp): the built-in sector (`builtInSectors` its sector
/// count, else 0) or a mesh file, its copies in `write`'s formats; the summary's line.
mesh::Mesh meshStage(SceneSection s, const SceneOverrides& overrides, const std::string& sceneDir,
                     const std::string& outDir, const linalg::Comm& comm, SceneSummary& summary, int& builtInSectors);
/// The static analysis and static.exo (StaticStage.cpp).
void staticStage(const analysis::StaticProblem& problem, const mesh::Mesh& mesh, const std::string& outDir,
                 linalg::CommPtr comm, SceneSummary& summary);
/// A matrix scene's forced response, frc.* (ForcedResponseOutput.cpp).
void forcedResponseStage(SceneSection& scene, const std::string& outDir,
                         const std::shared_ptr<continuation::TraceCheckpoints>& checkpoints, linalg::CommPtr comm,
                         SceneSummary& summary);

/// The run's mark in the directory (rank 0; RunDirectory.cpp), before anything is
/// written: a second run into it is refused on every rank; a previous run that did not
/// finish is said.
std::unique_ptr<RunManifest> claimOutputDirectory(const std::string& outDir, const std::string& source,
                                                  linalg::CommPtr comm, SceneSummary& summary);
/// <out>/checkpoints: emptied, or read back with --resume.
std::shared_ptr<io::TraceCheckpointDirectory> openCheckpoints(const std::string& checkpointDir,
                                                              const SceneOverrides& overrides, linalg::CommPtr comm);
/// The manifest marked failed with the run's error (said in the log where it cannot be).
void markFailed(RunManifest* manifest, const std::string& reason);

/// The most time samples per period a scene may ask for: every residual's cost grows in
/// proportion (a friction contact's march too), and 2e6 ran for minutes without a point
/// (issue 20). The largest shipped need is 4096 (the samples check of 2048).
constexpr int kMaxSamples = 1 << 16;

/// Writes a traced curve's <name>.csv, <name>.svg, <name>.h5 and <name>_harmonics.csv
/// (rank 0) and its lines for the summary.
void writeForcedResponse(const response::ForcedResponseSetup& setup, const response::ForcedResponseResult& result,
                         const std::string& outDir, const std::string& name, linalg::CommPtr comm,
                         SceneSummary& summary);

/// Traces the curve (response::solveForcedResponse) and writes <name>.csv, <name>.svg,
/// <name>.h5 and <name>_harmonics.csv (rank 0); lines for the summary. A curve without a
/// point is a SolverError.
response::ForcedResponseResult traceAndWriteForcedResponse(response::ForcedResponseSetup& setup,
                                                           const std::string& outDir, const std::string& name,
                                                           linalg::CommPtr comm, SceneSummary& summary);

fe::IsotropicElastic readMaterial(SceneSection section);

/// The sector's side faces from the scene's `cyclic` section, by part: the disc's
/// (cyclic in every analysis) and the shroud's (cyclic in a modal analysis with
/// configuration fixed_shroud; in the reduced models, which are cantilevered, the
/// shroud is free and its contact carries the coupling). One set of keys for every
/// analysis, so a mesh with its own set names works everywhere.
struct CyclicFaces {
  std::vector<std::string> discLeft{"disc_left"}, discRight{"disc_right"};
  std::vector<std::string> shroudLeft{"shroud_left"}, shroudRight{"shroud_right"};
  bool shroudCyclic = true;  ///< configuration: fixed_shroud (true) or cantilever
  /// The modal analysis's cyclic faces (disc, and shroud with fixed_shroud).
  std::vector<std::string> left() const;
  std::vector<std::string> right() const;
};
/// Reads configuration and the disc's and shroud's left and right node sets.
CyclicFaces readCyclicFaces(SceneSection& cyclic);

/// `axis_point` and `axis_direction` of a section (default: the z axis); InputError for a
/// zero direction.
mesh::RotationAxis readRotationAxis(SceneSection& section);
/// InputError under `speedKey` where the centrifugal stress scale rho (Omega r)^2 at the
/// mesh's outermost node passes 5 % of E: a disc torn apart long before (titanium bursts
/// near 1 %), so a wrong unit or a typo (rho 1e300, 1e9 rpm), not a speed to solve at.
/// InputError under `meshKey` where that radius is no bladed disc's in the material's
/// units (1 mm..20 m): a mesh in metres with the mm-N-s-t material, or in mm with SI.
void checkCentrifugalStrain(const fe::IsotropicElastic& material, double rpm, const mesh::Mesh& mesh,
                            const mesh::RotationAxis& axis, const std::string& speedKey, const std::string& meshKey);

/// `prestress` of a section: linear, nonlinear or none (`fallback` when absent);
/// InputError naming the key otherwise.
cyclic::PrestressKind readPrestressKind(SceneSection& section, const std::string& fallback);

/// `harmonics` of a section: a list of harmonics, or one number H meaning 0..H (H >= 1);
/// `defaultMax` when absent (0..defaultMax); `auto` (harmonics by an error target,
/// readHarmonicsTarget) starts from 0..1.
std::vector<int> readHarmonicList(SceneSection& section, int defaultMax);

/// `harmonics: auto`'s keys: harmonics_tolerance (default 0.01: the peak's relative change
/// over each of the last two raises of H) and harmonics_max (the highest H tried,
/// default `defaultMax`). tolerance 0 when the harmonics are given (then those keys are
/// refused).
struct HarmonicsTargetKeys {
  double tolerance = 0;
  int max = 0;
};
HarmonicsTargetKeys readHarmonicsTarget(SceneSection& section, int defaultMax);

/// `stability` of a section: auto (default), true or false; InputError naming the key otherwise.
response::ForcedResponseSetup::Stability readStability(SceneSection& section);

/// `harmonics_check_to` of a forced-response section: the highest harmonic the
/// harmonics check of a frequency curve raises H to (0 when absent: H + 1); given,
/// it must exceed the curve's H. With harmonics: auto, harmonics_max (the key refused).
int readHarmonicsCheckTo(SceneSection& section, int maxHarmonic, const HarmonicsTargetKeys& target = {});

/// report.md in the output directory: the run's summary, its figures (the SVGs the
/// stages wrote), the studies' tables and the stages' error against run time.
void writeRunReport(const std::string& outDir, const std::string& source, const SceneSummary& summary);

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
/// disc_goodman.svg; lines for the summary.
void writePeakStress(const PeakStressSpec& spec, const mesh::Mesh& mesh, const DiscReducedModels& models,
                     const DiscModelSpec& modelSpec, const PeakPoint& point, double excitationScale,
                     const std::string& outDir, linalg::CommPtr comm, SceneSummary& summary);

/// A value-list study's peak at one value (its frequency curve's largest point).
struct StudyPeak {
  double value = 0, peak = 0, omega = 0;
  Eigen::VectorXd x;  ///< the curve's point at its peak (a known peak for the peak studies)
};

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
void followDiscPeaks(const std::vector<PeakStudySpec>& studies, const mesh::Mesh& mesh, const DiscReducedModels& models,
                     const DiscPlan& plan, const ForcedResponseSetup& reference,
                     const ForcedResponseResult& referenceResult, double bandFromHz, double bandToHz,
                     const std::map<std::string, std::vector<StudyPeak>>& listed, const std::string& outDir,
                     linalg::CommPtr comm, SceneSummary& summary);

/// "peak memory after <stage>: ..." for the log (rank 0's, and the sum over the ranks).
void logPeakMemory(const std::string& stage, const linalg::CommPtr& comm);

/// What the modal stage takes from the scene (material, constraints, cyclic, modal,
/// diagrams), read and checked before any work: the sector's side faces paired.
struct ModalPlan {
  int sectors = 0;
  cyclic::CyclicSector sector;
  cyclic::ModalSweepProblem sweep;
  std::vector<int> engineOrders;  ///< diagrams/engine_orders
  bool writeMac = false;
};
ModalPlan readModalPlan(SceneSection& scene, const mesh::Mesh& mesh, int builtInSectors, const std::string& outDir);
/// diagrams/engine_orders (default 1..sectors).
std::vector<int> readEngineOrders(SceneSection diagrams, int sectors);

/// The modal stage: the prestressed modes of every nodal diameter at each speed of
/// modal/speeds_rpm, their Exodus files, frequencies.csv, MAC between speeds, and the
/// Campbell and SAFE diagrams.
void modalStage(const ModalPlan& plan, const mesh::Mesh& mesh, const std::string& outDir, linalg::CommPtr comm,
                SceneSummary& summary);

/// What the static stage takes from the scene (material, constraints, loads, solver).
analysis::StaticProblem readStaticProblem(SceneSection& scene, const mesh::Mesh& mesh);
/// The solver section (the static solve's linear solver).
void readStaticSolver(SceneSection solver, analysis::StaticProblem& problem);
/// The loads section: speed, axis, body force and nodal forces (their node sets checked).
void readStaticLoads(SceneSection loads, const mesh::Mesh& mesh, analysis::StaticProblem& problem);

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
/// disc_response/hysteresis_contacts: the contact pairs whose loops are written.
std::vector<int> readHysteresisContacts(SceneSection& d, const mesh::Mesh& mesh, const DiscResponseSpec& spec);

/// disc_response/studies' parameters (one frequency curve per listed value).
inline constexpr const char* kStudyNames[] = {"preload", "mu", "contact_stiffness", "force",
                                              "loss_factor", "harmonics", "modes", "clearance"};

/// A study value that reproduces the reference scene: disc_frc's files under the study's
/// name `tag` (DiscPeakStudies.cpp).
void copyReferenceCurve(const std::string& outDir, const std::string& tag, const std::string& what,
                        linalg::CommPtr comm, SceneSummary& summary);

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
