#pragma once
// Trace checkpoints (continuation/TraceCheckpoint.hpp) as HDF5 files in a directory,
// one per trace: <dir>/trace_<key>.h5, each replaced atomically. Schema:
//   /parameter [P], /x [P x n]                       the points
//   /tangent_known [P], /tangent_x [P x n], /tangent_p [P], /measure [P]
//   /direction_x [n], /segment_starts [S]
//   attributes: complete, finished, returned_to_start, reached, stop_reason,
//   failed_steps, the statistics, and the predictor-corrector's step, scales and counters
#include <string>

#include "cyclone/continuation/TraceCheckpoint.hpp"

namespace cyclone::io {

class TraceCheckpointDirectory : public continuation::TraceCheckpoints {
public:
  /// `readOnly`: loads, never saves (the other MPI ranks of a run that traces the same
  /// curves as rank 0, which saves them).
  explicit TraceCheckpointDirectory(std::string directory, bool readOnly = false)
      : dir_(std::move(directory)), readOnly_(readOnly) {}
  std::optional<continuation::TraceState> load(const std::string& key) override;
  void save(const std::string& key, const continuation::TraceState& state) override;
  const std::string& directory() const { return dir_; }

private:
  std::string path(const std::string& key) const { return dir_ + "/trace_" + key + ".h5"; }
  std::string dir_;
  bool readOnly_ = false;
};

}  // namespace cyclone::io
