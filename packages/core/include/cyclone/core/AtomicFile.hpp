#pragma once
// Nothing half-written: outputs are produced under a temporary name in the
// same directory and renamed over the final name only once complete.
#include <string>

namespace cyclone {

class AtomicFile {
public:
  explicit AtomicFile(std::string finalPath);
  ~AtomicFile();  // removes the temporary if commit() was never called
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  /// Where to write now.
  const std::string& tempPath() const { return temp_; }
  const std::string& finalPath() const { return final_; }
  /// Renames the temporary over the final path.
  void commit();

private:
  std::string final_, temp_;
  bool committed_ = false;
};

}  // namespace cyclone
