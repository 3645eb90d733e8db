#pragma once
// Nothing half-written: outputs are produced under a temporary name in the
// same directory and renamed over the final name only once complete.
#include <iosfwd>
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
  /// Writes `bytes` to the temporary, checked to the close (a full disk fails there too).
  void write(const char* bytes, std::size_t size) const;
  /// A stream written to tempPath(): closed, and if any of its writes or its close failed,
  /// fail().
  void check(std::ofstream& out) const;
  /// Throws Error "cannot write <final path>: <the system's reason>" (errno: "No space
  /// left on device", "File too large", ...).
  [[noreturn]] void fail() const;

private:
  std::string final_, temp_;
  bool committed_ = false;
};

}  // namespace cyclone
