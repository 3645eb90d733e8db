// Runs a scene: reads its analyses, claims the output directory, and runs the stages
// (mesh, static, modal, disc, or a matrix-defined forced response) in order.
#include "cyclone/scenes/SceneRunner.hpp"

#include <Teuchos_Comm.hpp>
#include <Teuchos_CommHelpers.hpp>

#include <optional>
#include <algorithm>
#include <set>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>

#include "DemoScene.hpp"
#include "cyclone/analysis/StaticAnalysis.hpp"
#include "cyclone/continuation/ArclengthContinuation.hpp"
#include "cyclone/core/AddressSpace.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/io/TraceCheckpointDirectory.hpp"
#include "cyclone/core/Error.hpp"
#include "cyclone/core/Log.hpp"
#include "cyclone/scenes/ForcedResponseScene.hpp"
#include "cyclone/scenes/SceneSection.hpp"
#include "RunManifest.hpp"
#include "DiscStages.hpp"

namespace cyclone::scenes {

const char* demoScene() { return demoSceneYaml(); }

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
  if (manifest) {
    if (const auto left = manifest->earlierFilesLeft(summary.written); !left.empty()) {
      std::string named;
      for (std::size_t i = 0; i < left.size() && i < 3; ++i) named += (i ? ", " : "") + left[i];
      const std::string warning = std::to_string(left.size()) + " file" + (left.size() > 1 ? "s" : "") +
                                  " of an earlier run into " + outDir + " stay beside this run's (" + named +
                                  (left.size() > 3 ? ", ..." : "") + "): run_manifest.txt lists this run's";
      log::warn(warning);
      summary.computed.push_back("warning: " + warning);
    }
    manifest->complete(summary.written);
  }
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
  // Every analysis but writing a mesh calls LAPACK (CHOLMOD's factorizations, the dense
  // LU of a matrix scene's Newton steps): OpenBLAS's work buffer taken now, or its
  // shortfall under an address-space limit said now, not waited for by OpenBLAS for ever.
  if (!(analyses.size() == 1 && analyses.front() == "mesh")) takeBlasWorkBuffer();
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
  std::vector<std::string> meshCopies;
  auto mesh = meshStage(scene.section("mesh"), overrides, sceneDir, summary, builtInSectors, meshCopies);
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
  writeMeshCopies(mesh, meshCopies, outDir, *comm, summary);
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
