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
#include "cyclone/hbm/HarmonicBalanceSystem.hpp"
#include "cyclone/fe/LinearAlgebra.hpp"
#include "cyclone/fe/Material.hpp"
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

class RunManifest;

/// The mesh stage (MeshStage.cpp): the built-in sector (`builtInSectors` its sector
/// count, else 0) or a mesh file, `write`'s formats checked into `copies`; the summary's line.
mesh::Mesh meshStage(SceneSection s, const SceneOverrides& overrides, const std::string& sceneDir,
                     SceneSummary& summary, int& builtInSectors, std::vector<std::string>& copies);
/// The mesh's copies in those formats (mesh.exo, mesh.inp), written once the whole scene
/// is checked: a scene refused after its mesh was built left them behind, over a complete
/// run's (issue 49's sixth probe).
void writeMeshCopies(const mesh::Mesh& mesh, const std::vector<std::string>& copies, const std::string& outDir,
                     const linalg::Comm& comm, SceneSummary& summary);
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

}  // namespace cyclone::scenes
