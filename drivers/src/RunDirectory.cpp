// The run's output directory: claimed by its manifest (a second run refused, an
// unfinished one said), its checkpoints opened for --resume, marked failed on an error.
#include <Teuchos_CommHelpers.hpp>

#include <filesystem>

#include "cyclone/io/TraceCheckpointDirectory.hpp"
#include "cyclone/core/Error.hpp"
#include "cyclone/core/Log.hpp"
#include "cyclone/scenes/SceneSection.hpp"
#include "SceneStages.hpp"
#include "RunManifest.hpp"

namespace cyclone::scenes {

// The run's mark in the directory (rank 0), before anything is written: a second run
// into it is refused on every rank; a previous run that did not finish is said.
std::unique_ptr<RunManifest> claimOutputDirectory(const std::string& outDir, const std::string& source,
                                                linalg::CommPtr comm, SceneSummary& summary) {
  std::unique_ptr<RunManifest> manifest;
  std::string refused, previousUnfinished;
  if (comm->getRank() == 0) {
    // A file of that name (or a parent that is one) gave the raw "filesystem error" (issue
    // 49's fourth probe): said as the output directory's fault, on every rank.
    std::error_code made;
    std::filesystem::create_directories(outDir, made);
    if (made || !std::filesystem::is_directory(outDir)) {
      refused = "the output directory cannot be made there (" +
                (made ? made.message() : std::string("a file of that name exists")) +
                "): give output_directory or --output a directory's path";
    } else {
      try {
        manifest = std::make_unique<RunManifest>(outDir, source, previousUnfinished);
      } catch (const InputError& e) {
        refused = e.what();
      }
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

}  // namespace cyclone::scenes
