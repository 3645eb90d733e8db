#pragma once
// Results kept as they are computed, so a killed run that is resumed reads back what
// it had finished instead of computing it again (the cyclic modes of each nodal
// diameter: CyclicModalProblem::checkpoints). A result is a vector of numbers filed
// under a key that digests everything it depends on (ContentHash), so a changed
// input misses and is computed afresh. io::ResultCheckpointDirectory keeps them as
// HDF5 files.
#include <optional>
#include <string>
#include <vector>

namespace cyclone {

class ResultCheckpoints {
public:
  virtual ~ResultCheckpoints() = default;
  /// The values saved under `key`; none when there are none or they cannot be read.
  virtual std::optional<std::vector<double>> load(const std::string& key) = 0;
  /// Saved atomically (a kill during the save leaves no partial result).
  virtual void save(const std::string& key, const std::vector<double>& values) = 0;
};

}  // namespace cyclone
