#pragma once
// Result checkpoints (core/ResultCheckpoints.hpp) as HDF5 files in a directory:
// <dir>/result_<key>.h5 holding the dataset /values, each written atomically.
#include <string>

#include "cyclone/core/ResultCheckpoints.hpp"

namespace cyclone::io {

class ResultCheckpointDirectory : public ResultCheckpoints {
public:
  explicit ResultCheckpointDirectory(std::string directory) : dir_(std::move(directory)) {}
  std::optional<std::vector<double>> load(const std::string& key) override;
  void save(const std::string& key, const std::vector<double>& values) override;

private:
  std::string path(const std::string& key) const { return dir_ + "/result_" + key + ".h5"; }
  std::string dir_;
};

}  // namespace cyclone::io
