#pragma once
// A run's mark in its output directory: `run_manifest.txt` says "running" from the
// start (with the scene, the process and the time), and "complete" with the files
// written, or "failed" with the reason, at the end; a run killed on the way leaves
// "running", so its directory is never mistaken for a finished run's; one stopped by
// SIGTERM or SIGINT says "interrupted" (its checkpoints kept for --resume). A lock file
// held for the run's life (flock: released by the kernel when the process dies)
// refuses a second run into the same directory while the first is alive.
#include <string>
#include <vector>

namespace cyclone::scenes {

class RunManifest {
public:
  /// Takes the directory's lock (InputError naming the directory and the other run when
  /// it is held), removes the temporary files a killed run left in it (said in
  /// `previousUnfinished`) and marks the run as running. `previousUnfinished` is filled when a
  /// former run into the directory stopped without finishing (its manifest said running).
  RunManifest(const std::string& outDir, const std::string& scene, std::string& previousUnfinished);
  ~RunManifest();
  RunManifest(const RunManifest&) = delete;
  RunManifest& operator=(const RunManifest&) = delete;

  /// The files the directory's earlier manifest listed that this run did not write and
  /// that are still there, relative to the directory: another scene's products beside this
  /// run's (a Duffing run into a disc run's directory left disc_frc.* without a word).
  std::vector<std::string> earlierFilesLeft(const std::vector<std::string>& written) const;
  void complete(const std::vector<std::string>& written);
  void fail(const std::string& reason);

private:
  void write(const std::string& status, const std::string& extra);
  std::string dir_, scene_, started_;
  std::vector<std::string> earlierFiles_;  ///< the earlier manifest's files, relative
  int lock_ = -1;
  bool finished_ = false;
};

}  // namespace cyclone::scenes
