// Runs a scene: reads its analyses, claims the output directory, and runs the stages
// (mesh, static, modal, disc, or a matrix-defined forced response) in order.
#include "cyclone/scenes/SceneRunner.hpp"

#include <Teuchos_Comm.hpp>
#include <Teuchos_CommHelpers.hpp>

#include <optional>
#include <Teuchos_YamlParameterListCoreHelpers.hpp>

#include <algorithm>
#include <set>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>

#include "DemoScene.hpp"
#include "cyclone/analysis/StaticAnalysis.hpp"
#include "cyclone/continuation/ArclengthContinuation.hpp"
#include "cyclone/core/AtomicFile.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/io/ResultCheckpointDirectory.hpp"
#include "cyclone/io/TraceCheckpointDirectory.hpp"
#include "cyclone/core/Error.hpp"
#include "cyclone/core/Log.hpp"
#include "cyclone/mesh/AbaqusIO.hpp"
#include "cyclone/mesh/ExodusIO.hpp"
#include "cyclone/mesh/MeshReader.hpp"
#include "cyclone/mesh/ShroudedSectorGenerator.hpp"
#include "cyclone/scenes/ForcedResponseScene.hpp"
#include "cyclone/scenes/SceneSection.hpp"
#include "RunManifest.hpp"
#include "SceneStages.hpp"

namespace cyclone::scenes {

const char* demoScene() { return demoSceneYaml(); }

namespace {

mesh::ShroudedSectorParameters readSectorParameters(SceneSection s) {
  mesh::ShroudedSectorParameters p;
  p.sectors = s.getInt("sectors", p.sectors);
  p.boreRadius = s.getDouble("bore_radius", p.boreRadius);
  p.rimRadius = s.getDouble("rim_radius", p.rimRadius);
  p.discThickness = s.getDouble("disc_thickness", p.discThickness);
  p.bladeHeight = s.getDouble("blade_height", p.bladeHeight);
  p.bladeChord = s.getDouble("blade_chord", p.bladeChord);
  p.bladeThickness = s.getDouble("blade_thickness", p.bladeThickness);
  p.bladeStaggerDeg = s.getDouble("blade_stagger_deg", p.bladeStaggerDeg);
  p.shroudThickness = s.getDouble("shroud_thickness", p.shroudThickness);
  p.shroudWidth = s.getDouble("shroud_width", p.shroudWidth);
  p.meshSize = s.getDouble("mesh_size", p.meshSize);
  p.elementOrder = s.getInt("element_order", p.elementOrder);
  s.rejectUnknownKeys();
  p.validate(s.location());
  return p;
}

// The mesh stage: built-in generator or a file; optional copies in Exodus and .inp.
mesh::Mesh meshStage(SceneSection s, const SceneOverrides& overrides, const std::string& sceneDir,
                     const std::string& outDir, const linalg::Comm& comm, SceneSummary& summary,
                     int& builtInSectors) {
  builtInSectors = 0;
  const bool writer = comm.getRank() == 0;
  const std::string source = s.getString("source", "shrouded_sector");
  const auto write = s.getStringList("write", {});
  SceneSection sector = s.section("shrouded_sector");
  mesh::Mesh mesh;
  if (source == "shrouded_sector") {
    auto p = readSectorParameters(sector);
    if (overrides.meshSize) p.meshSize = *overrides.meshSize;
    mesh = mesh::generateShroudedSector(p);
    builtInSectors = p.sectors;
  } else {
    if (overrides.meshSize)
      throw InputError("--mesh-size", "applies to the built-in sector; this scene reads its mesh from '" + source + "'");
    // The built-in sector's keys do not apply to a mesh read from a file: say so, not
    // "unknown key (known here: )" (issue 20).
    if (s.has("shrouded_sector"))
      throw InputError(s.where("shrouded_sector"), "applies to source: shrouded_sector only; the mesh is read from '" +
                                                       source + "' (remove the block, or the source key)");
    const std::filesystem::path path = std::filesystem::path(source).is_absolute()
                                           ? std::filesystem::path(source)
                                           : std::filesystem::path(sceneDir) / source;
    log::info("reading mesh " + path.string());
    mesh = mesh::readMesh(path.string());
  }
  s.rejectUnknownKeys();
  std::ostringstream line;
  line << "mesh: " << mesh.numNodes() << " nodes, " << mesh.numElements() << " elements (" << mesh.source << ")";
  summary.computed.push_back(line.str());
  for (const auto& format : write) {
    if (format == "exodus") {
      const std::string path = outDir + "/mesh.exo";
      if (writer) mesh::writeExodus(path, mesh);
      summary.written.push_back(path);
    } else if (format == "inp") {
      const std::string path = outDir + "/mesh.inp";
      if (writer) mesh::writeAbaqusInp(path, mesh);
      summary.written.push_back(path);
    } else {
      throw InputError(s.where("write"), "unknown mesh format '" + format + "' (use exodus, inp)");
    }
  }
  return mesh;
}



}  // namespace

namespace {

void forcedResponseStage(SceneSection& scene, const std::string& outDir,
                         const std::shared_ptr<continuation::TraceCheckpoints>& checkpoints, linalg::CommPtr comm,
                         SceneSummary& summary) {
  auto setup = readForcedResponseSetup(scene);
  setup.continuation.checkpoints = checkpoints;
  if (setup.fallback) setup.fallback->checkpoints = checkpoints;
  for (const auto& note : setup.notes) {
    log::info(note);
    summary.computed.push_back(note);
  }
  traceAndWriteForcedResponse(setup, outDir, "frc", comm, summary);
}

}  // namespace

analysis::StaticProblem readStaticProblem(SceneSection& scene, const mesh::Mesh& mesh) {
  analysis::StaticProblem problem;
  problem.material = readMaterial(scene.section("material"));
  {
    auto c = scene.section("constraints");
    problem.fixedNodeSets = c.getStringList("fixed_node_sets", {});
    c.rejectUnknownKeys();
    for (const auto& name : problem.fixedNodeSets)
      if (!mesh.nodeSets.count(name)) mesh.nodeSet(name);  // throws naming the mesh and its sets
  }
  readStaticLoads(scene.section("loads"), mesh, problem);
  checkCentrifugalStrain(problem.material, problem.speedRpm, mesh, problem.axis, scene.where("loads/speed_rpm"));
  readStaticSolver(scene.section("solver"), problem);
  if (problem.fixedNodeSets.empty())
    throw InputError(scene.where("constraints/fixed_node_sets"),
                     "a static analysis needs fixed node sets (the model would move as a rigid body)");
  return problem;
}

void readStaticSolver(SceneSection s, analysis::StaticProblem& problem) {
  problem.solver.kind = solvers::linearSolverKindFromName(s.getString("type", "direct"), s.where("type"));
  problem.solver.tolerance = s.getDouble("tolerance", problem.solver.tolerance);
  problem.solver.maxIterations = s.getInt("max_iterations", problem.solver.maxIterations);
  s.rejectUnknownKeys();
}

void readStaticLoads(SceneSection l, const mesh::Mesh& mesh, analysis::StaticProblem& problem) {
  problem.speedRpm = l.getDouble("speed_rpm", 0.0);
  if (!(problem.speedRpm >= 0 && std::isfinite(problem.speedRpm)))
    throw InputError(l.where("speed_rpm"), std::to_string(problem.speedRpm) +
                                               ": must be >= 0 and finite (the centrifugal load does not depend on "
                                               "the sense of rotation: give its magnitude)");
  problem.axis = readRotationAxis(l);
  const auto b = l.getVector3("body_force", {0, 0, 0});
  problem.bodyForce = Eigen::Vector3d(b[0], b[1], b[2]);
  auto forces = l.section("nodal_forces");
  for (const auto& name : forces.sectionNames()) {
    auto f = forces.section(name);
    analysis::NodalForce load;
    load.nodeSet = f.getString("node_set", "");
    const auto v = f.getVector3("force", {0, 0, 0});
    load.forcePerNode = Eigen::Vector3d(v[0], v[1], v[2]);
    f.rejectUnknownKeys();
    mesh.nodeSet(load.nodeSet);
    problem.nodalForces.push_back(load);
  }
  forces.rejectUnknownKeys();
  l.rejectUnknownKeys();
}

namespace {

void staticStage(const analysis::StaticProblem& problem, const mesh::Mesh& mesh, const std::string& outDir,
                 linalg::CommPtr comm, SceneSummary& summary) {
  {
    std::ostringstream msg;
    msg << "linear static analysis at " << problem.speedRpm << " rpm";
    log::info(msg.str());
  }
  const auto result = analysis::solveStatic(mesh, problem, comm);
  const std::string path = outDir + "/static.exo";
  if (comm->getRank() == 0) analysis::writeStaticResult(path, mesh, result);
  std::ostringstream line;
  line << "static: " << result.equations << " equations, max |u| = " << result.maxDisplacement << " at node "
       << (result.maxDisplacementNode >= 0 ? mesh.nodeIds[result.maxDisplacementNode] : -1)
       << ", max von Mises = " << result.maxVonMises << ", residual " << result.solve.relativeResidual;
  summary.computed.push_back(line.str());
  summary.written.push_back(path);
}

}  // namespace

namespace {
void runStages(SceneSection& scene, const std::vector<std::string>& analyses, const SceneOverrides& overrides,
               const std::string& source, const std::string& sceneDir, const std::string& outDir,
               const std::shared_ptr<continuation::TraceCheckpoints>& checkpoints, linalg::CommPtr comm,
               SceneSummary& summary, std::map<std::string, std::string>& unreadNotes);
}  // namespace

namespace {

// The analyses a scene asks for; its top-level keys and (for anything with a mass
// matrix) its density checked before anything runs, so a typo costs no computation.
std::vector<std::string> readAnalyses(SceneSection& scene) {
  const auto analyses = scene.getStringList("analysis", {"static"});
  if (analyses.empty())
    throw InputError(scene.where("analysis"), "lists no analysis (use static, modal, mesh, reduced_model, "
                                              "disc_response or forced_response, or a list of them)");
  for (const auto& a : analyses)
    if (a != "static" && a != "mesh" && a != "modal" && a != "forced_response" && a != "reduced_model" &&
        a != "disc_response")
      throw InputError(scene.where("analysis"),
                       "unknown analysis '" + a +
                           "' (use static, modal, mesh, reduced_model, disc_response or forced_response, or a list)");
  auto wants = [&](const char* a) { return std::find(analyses.begin(), analyses.end(), a) != analyses.end(); };
  scene.rejectKeysOtherThan({"analysis", "output_directory", "mesh", "material", "constraints", "loads", "solver",
                             "cyclic", "modal", "diagrams", "system", "nonlinear_elements", "excitation", "harmonics",
                             "harmonics_tolerance", "harmonics_max", "samples", "continuation", "output", "static_loads", "reduced_model",
                             "disc_response"});
  // The two kinds of scene read different sections, and a section of the other kind would
  // be ignored whatever it holds (issue 49: `modal: {modes_per_ndd: 3}` in a matrix scene
  // ran, exit 0); a matrix system's response runs alone (the mesh stages would not run).
  const std::set<std::string> matrixSections{"system",  "nonlinear_elements", "excitation", "harmonics",
                                             "harmonics_tolerance", "harmonics_max", "samples", "continuation",
                                             "output",  "static_loads"},
      meshSections{"mesh", "material", "constraints", "loads", "solver", "cyclic", "modal", "diagrams",
                   "reduced_model", "disc_response"};
  const bool matrix = wants("forced_response");
  if (matrix && analyses.size() > 1)
    throw InputError(scene.where("analysis"), "forced_response (a system given by its matrices) runs alone: the "
                                              "other analyses need a mesh (run them in a scene of their own)");
  for (const auto& key : matrix ? meshSections : matrixSections)
    if (scene.has(key)) {
      std::string used;
      for (const auto& k : matrix ? matrixSections : meshSections) used += (used.empty() ? "" : ", ") + k;
      throw InputError(scene.where(key), std::string("is not read by ") +
                                             (matrix ? "a matrix system's forced_response, which takes "
                                                     : "the mesh analyses, which take ") +
                                             used + ": remove it, or check the analysis");
    }
  // A mass matrix needs a density: with rho = 0 the eigen-solver spun for minutes (issue 20).
  if (wants("modal") || wants("disc_response") || wants("reduced_model")) {
    auto m = scene.section("material");
    if (const auto material = readMaterial(m); !(material.rho > 0))
      throw InputError(m.where("rho"), "must be positive for modes, reduced models and forced responses (the mass "
                                       "matrix), got " + std::to_string(material.rho));
  }
  return analyses;
}

// The run's mark in the directory (rank 0), before anything is written: a second run
// into it is refused on every rank; a previous run that did not finish is said.
std::unique_ptr<RunManifest> claimOutputDirectory(const std::string& outDir, const std::string& source,
                                                linalg::CommPtr comm, SceneSummary& summary) {
  if (comm->getRank() == 0) std::filesystem::create_directories(outDir);
  std::unique_ptr<RunManifest> manifest;
  std::string refused, previousUnfinished;
  if (comm->getRank() == 0) {
    try {
      manifest = std::make_unique<RunManifest>(outDir, source, previousUnfinished);
    } catch (const InputError& e) {
      refused = e.what();
    }
  }
  int isRefused = refused.empty() ? 0 : 1;
  Teuchos::broadcast(*comm, 0, &isRefused);
  if (isRefused) throw InputError(outDir, comm->getRank() == 0 ? refused : "another run is writing into it");
  if (!previousUnfinished.empty()) {
    log::warn(previousUnfinished);
    summary.computed.push_back("warning: " + previousUnfinished);
  }
  return manifest;
}

// Curves save their traces in <out>/checkpoints as they go (rank 0 writes; the others,
// which trace the same curves, only read). --resume reads them: finished traces are read
// back, the one the kill interrupted continues; any other run starts without them.
std::shared_ptr<io::TraceCheckpointDirectory> openCheckpoints(const std::string& checkpointDir,
                                                              const SceneOverrides& overrides, linalg::CommPtr comm) {
  if (!(overrides.checkpointSeconds >= 0))
    throw InputError("--checkpoint-seconds", "must be zero or positive, got " + std::to_string(overrides.checkpointSeconds));
  if (comm->getRank() == 0) {
    if (!overrides.resume) {
      std::filesystem::remove_all(checkpointDir);
    } else if (!std::filesystem::exists(checkpointDir)) {
      log::warn("--resume: " + checkpointDir + " holds nothing to continue (the run before completed, or saved "
                "no curve): everything is computed");
    } else {
      log::info("--resume: traces saved in " + checkpointDir + " are read back or continued");
    }
  }
  Teuchos::barrier(*comm);
  auto checkpoints = std::make_shared<io::TraceCheckpointDirectory>(checkpointDir, comm->getRank() != 0);
  checkpoints->intervalSeconds = overrides.checkpointSeconds;
  return checkpoints;
}

}  // namespace

namespace {

// The manifest marked failed with the run's error; where even that cannot be written (a
// full disk), said in the log: the error that stopped the run is the one reported.
void markFailed(RunManifest* manifest, const std::string& reason) {
  if (!manifest) return;
  try {
    manifest->fail(reason);
  } catch (const std::exception& e) {
    log::warn(std::string("the run's manifest could not be marked failed: ") + e.what());
  }
}

}  // namespace

SceneSummary runSceneText(const std::string& yaml, const std::string& source, const SceneOverrides& overrides,
                          linalg::CommPtr comm) {
  const auto root = parseSceneYaml(yaml, source);
  const std::string sceneDir = std::filesystem::path(source).has_parent_path()
                                   ? std::filesystem::path(source).parent_path().string()
                                   : ".";
  // Teuchos names the root list after the single top-level key.
  if (root->name() != "cyclone" && !root->isSublist("cyclone"))
    throw InputError(source, "the scene's top-level key must be 'cyclone'");
  const Teuchos::ParameterList& top = root->isSublist("cyclone") ? root->sublist("cyclone") : *root;
  SceneSection scene(top, source, "cyclone");
  SceneSummary summary;
  std::map<std::string, std::string> unreadNotes;  // per section no analysis read: whether its keys were checked
  const auto analyses = readAnalyses(scene);
  const std::string outDir = overrides.outputDirectory ? *overrides.outputDirectory
                                                       : scene.getString("output_directory", "cyclone_out");
  if (overrides.outputDirectory) scene.getString("output_directory", "");
  auto manifest = claimOutputDirectory(outDir, source, comm, summary);
  const std::string checkpointDir = outDir + "/checkpoints";
  const auto checkpoints = openCheckpoints(checkpointDir, overrides, comm);
  try {
    runStages(scene, analyses, overrides, source, sceneDir, outDir, checkpoints, comm, summary, unreadNotes);
  } catch (const InputError& e) {
    // The library names the entry ("excitation: DOF 5 out of range"); the scene file is
    // added where the message does not start with it (issue 20).
    const std::string what = e.what();
    markFailed(manifest.get(), what);
    if (what.rfind(source, 0) == 0) throw;
    throw InputError(source, what);
  } catch (const std::exception& e) {
    markFailed(manifest.get(), e.what());
    throw;
  }
  // A section of this kind of scene that these analyses did not read (e.g. modal in a
  // static scene): its keys were not checked, so said rather than passed over.
  for (const auto& key : scene.unreadKeys()) {
    std::string listed;
    for (const auto& a : analyses) listed += (listed.empty() ? "" : ", ") + a;
    const auto note = unreadNotes.find(key);
    const std::string warning = "'" + key + "' was not read by the analyses listed (" + listed + "): " +
                                (note != unreadNotes.end() ? note->second + ", its values not used"
                                                           : "its keys were not checked");
    log::warn(warning);
    summary.computed.push_back("warning: " + warning);
  }
  if (manifest) manifest->complete(summary.written);
  if (comm->getRank() == 0) {
    std::error_code ignored;  // a leftover directory costs disk space, not the run
    std::filesystem::remove_all(checkpointDir, ignored);
  }
  return summary;
}

namespace {

// The sections of a mesh scene that the analyses listed do not read, read anyway by the
// reader of the analysis that takes them, on a copy of the scene (so they stay unread for
// the warning after the run): an unknown key or a bad value in them is refused before any
// work, as in a section that is read (issue 49: `loads: {speed_rmp: 5000}` in a modal
// scene, `modal: {modes_per_ndd: 3}` in a static scene ran, exit 0). Where
// that reader stops at another section the listed analyses do not need (a reduced_model
// section in a mesh scene without constraints), the section could not be checked: what
// is returned says so, per section, for the warning.
std::map<std::string, std::string> checkUnreadSections(const SceneSection& scene, const mesh::Mesh& mesh,
                                                       int builtInSectors, const std::string& outDir,
                                                       const std::shared_ptr<continuation::TraceCheckpoints>& checkpoints) {
  const auto unread = scene.unreadKeys();
  std::map<std::string, std::string> notes;
  auto isUnread = [&](const char* key) { return std::find(unread.begin(), unread.end(), key) != unread.end(); };
  // Runs a reader for the unread `sections`: an error inside one of them is the scene's;
  // one elsewhere leaves them unchecked.
  // `alone`: the reader reads no other section, so every error it raises is the section's.
  auto attempt = [&](std::vector<std::string> sections, bool alone, const std::function<void(SceneSection&)>& read) {
    std::vector<std::string> mine;
    for (const auto& name : sections)
      if (isUnread(name.c_str())) mine.push_back(name);
    if (mine.empty()) return;
    SceneSection copy = scene;
    try {
      read(copy);
      for (const auto& name : mine) notes[name] = "its keys were checked";
    } catch (const InputError& e) {
      const std::string what = e.what();
      if (alone) throw;
      for (const auto& name : mine) {
        const std::string key = scene.where(name);  // "<file>: parameter 'cyclone/<name>'"
        const std::string path = key.substr(key.find('\'') + 1, key.size() - key.find('\'') - 2);
        if (what.find("'" + path + "'") != std::string::npos || what.find("'" + path + "/") != std::string::npos) throw;
      }
      for (const auto& name : mine) notes[name] = "its keys could not be checked (" + what + ")";
    }
  };
  attempt({"material"}, true, [](SceneSection& c) { readMaterial(c.section("material")); });
  attempt({"constraints"}, true, [&](SceneSection& c) {
    auto s = c.section("constraints");
    for (const auto& name : s.getStringList("fixed_node_sets", {})) mesh.nodeSet(name);
    s.rejectUnknownKeys();
  });
  attempt({"loads"}, true, [&](SceneSection& c) {
    analysis::StaticProblem problem;
    readStaticLoads(c.section("loads"), mesh, problem);
  });
  attempt({"solver"}, true, [](SceneSection& c) {
    analysis::StaticProblem problem;
    readStaticSolver(c.section("solver"), problem);
  });
  attempt({"cyclic", "modal", "diagrams"}, false, [&](SceneSection& c) { readModalPlan(c, mesh, builtInSectors, outDir); });
  if (scene.has("disc_response"))
    attempt({"reduced_model", "disc_response"}, false,
            [&](SceneSection& c) { readDiscStagePlan(c, mesh, builtInSectors, true, outDir, checkpoints); });
  else
    attempt({"reduced_model"}, false, [&](SceneSection& c) {
      auto r = c.section("reduced_model");
      auto d = c.section("disc_response");
      readDiscPlan(c, r, d, mesh, builtInSectors, false, outDir, false);
    });
  return notes;
}

void runStages(SceneSection& scene, const std::vector<std::string>& analyses, const SceneOverrides& overrides,
               const std::string& source, const std::string& sceneDir, const std::string& outDir,
               const std::shared_ptr<continuation::TraceCheckpoints>& checkpoints, linalg::CommPtr comm,
               SceneSummary& summary, std::map<std::string, std::string>& unreadNotes) {
  auto wants = [&](const char* a) { return std::find(analyses.begin(), analyses.end(), a) != analyses.end(); };
  if (wants("forced_response")) {
    // Matrix-defined systems need no mesh (--mesh-size was ignored, exit 0; issue 49 probe).
    if (overrides.meshSize)
      throw InputError("--mesh-size", "applies to the built-in sector (mesh: source: shrouded_sector); this scene is "
                                      "a system given by its matrices (forced_response)");
    Timer stage;
    forcedResponseStage(scene, outDir, checkpoints, comm, summary);
    summary.stages.push_back({"forced response", stage.seconds(), "see the samples check"});
    if (comm->getRank() == 0) writeRunReport(outDir, source, summary);
    summary.written.push_back(outDir + "/report.md");
    return;
  }
  int builtInSectors = 0;
  Timer stage;
  auto mesh = meshStage(scene.section("mesh"), overrides, sceneDir, outDir, *comm, summary, builtInSectors);
  // A node in no element has no stiffness: named here, not by the factorization's
  // "not positive definite" (issue 20). Writing the mesh alone does not need it.
  if (const auto orphans = mesh::orphanNodes(mesh);
      !orphans.empty() && (wants("static") || wants("modal") || wants("disc_response") || wants("reduced_model"))) {
    std::ostringstream ids;
    for (std::size_t i = 0; i < std::min<std::size_t>(orphans.size(), 5); ++i)
      ids << (i ? ", " : "") << mesh.nodeIds[std::size_t(orphans[i])];
    if (orphans.size() > 5) ids << ", ...";
    throw InputError(mesh.source, std::to_string(orphans.size()) + " node" + (orphans.size() > 1 ? "s" : "") +
                                      " in no element (id " + ids.str() +
                                      "): nothing holds them, so every solve would be singular; remove them");
  }
  summary.stages.push_back({"mesh", stage.seconds(), "element Jacobians checked positive at every integration point"});
  // Every stage's part of the scene is read and checked before the first of them runs: a
  // bad key in disc_response must not wait for the modes (issue 49).
  std::optional<analysis::StaticProblem> staticProblem;
  std::optional<ModalPlan> modalPlan;
  std::optional<DiscStagePlan> discPlan;
  if (wants("static")) staticProblem = readStaticProblem(scene, mesh);
  if (wants("modal")) modalPlan = readModalPlan(scene, mesh, builtInSectors, outDir);
  if (wants("disc_response") || wants("reduced_model"))
    discPlan.emplace(readDiscStagePlan(scene, mesh, builtInSectors, wants("disc_response"), outDir, checkpoints));
  unreadNotes = checkUnreadSections(scene, mesh, builtInSectors, outDir, checkpoints);
  if (staticProblem) {
    stage.restart();
    staticStage(*staticProblem, mesh, outDir, comm, summary);
    summary.stages.push_back({"static (linear, centrifugal)", stage.seconds(), summary.computed.back()});
  }
  if (modalPlan) {
    stage.restart();
    modalStage(*modalPlan, mesh, outDir, comm, summary);
    summary.stages.push_back({"prestress and cyclic modes", stage.seconds(),
                              "every mode's backward error ||K x - l M x|| / ((||K||_F + |l| ||M||_F) ||x||) below 1e-6, its value from a Rayleigh-Ritz on the solver's vectors matching the solver's value"});
  }
  if (discPlan) discStages(*discPlan, mesh, outDir, comm, summary);
  if (comm->getRank() == 0) writeRunReport(outDir, source, summary);
  summary.written.push_back(outDir + "/report.md");
}

}  // namespace

SceneSummary runSceneFile(const std::string& path, const SceneOverrides& overrides, linalg::CommPtr comm) {
  if (std::filesystem::is_directory(path))
    throw InputError(path, "is a directory, not a scene (a YAML file whose top-level key is 'cyclone')");
  std::ifstream in(path);
  if (!in) throw InputError(path, "cannot open the scene file");
  std::stringstream text;
  text << in.rdbuf();
  return runSceneText(text.str(), path, overrides, comm);
}

}  // namespace cyclone::scenes
