#pragma once
// The nodal shapes of one nodal diameter's modes, held in memory or in a scratch file.
// A modal sweep keeps every solved nodal diameter's shapes until its results are
// written, and on the built-in sector at 42k DOFs those are 70 MB held through every
// later factorization, the sweep's memory peak; in a scratch file they cost the
// process nothing until read back (by the Exodus writer, the Campbell diagram's
// family tracking or a checkpoint).
#include <array>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

namespace cyclone::cyclic {

using NodalField = std::vector<std::array<double, 3>>;

/// One mode's shape: real part (copy a) and imaginary part (copy b; zero for a nodal
/// diameter with one copy).
struct ModeShape {
  NodalField real, imag;
};

class ModeShapes {
public:
  std::size_t size() const { return count_; }
  bool empty() const { return count_ == 0; }
  /// Appends a shape (an empty imaginary part: zero, not stored). Every shape of one
  /// store has the same number of nodes and either has an imaginary part or none.
  void push_back(const ModeShape& shape);
  /// Shape i (read back from the scratch file when there); the imaginary part has the
  /// real part's size, zero when none is stored.
  ModeShape operator[](std::size_t i) const;
  std::size_t numNodes() const { return nodes_; }

  /// Moves the shapes held in memory, and every later one, into an unnamed file in
  /// `directory`: one file per directory for every store of the process (a sweep over
  /// many speeds and nodal diameters holds one descriptor), removed when the last store
  /// using it goes. Copies of a store read the same shapes; what a copy appends goes to
  /// its own place. Error naming the directory when it cannot be written.
  void moveToScratchFile(const std::string& directory);
  bool inScratchFile() const { return file_ != nullptr; }

  struct File;  ///< a scratch file (ModeShapes.cpp)

private:
  std::size_t valuesPerShape() const { return (withImag_ ? 6 : 3) * nodes_; }
  std::size_t nodes_ = 0, count_ = 0;
  bool withImag_ = false;
  std::vector<double> memory_;  // count_ x valuesPerShape(), when not in a file
  std::shared_ptr<File> file_;
  std::vector<std::size_t> offsets_;  // each shape's place in the file (bytes)
};

}  // namespace cyclone::cyclic
