#pragma once
// Degrees of freedom: 3 displacement components per node. Constrained
// components are eliminated (not penalised), so K and M stay symmetric
// positive (semi)definite and eigenproblems have no spurious modes.
#include <array>
#include <string>
#include <vector>

#include "cyclone/fe/DofTransform.hpp"
#include "cyclone/mesh/Mesh.hpp"

namespace cyclone::fe {

using mesh::Index;

class DofMap {
public:
  explicit DofMap(Index numNodes);

  /// Fixes the chosen components (x, y, z) of the given nodes to zero.
  void constrain(const std::vector<Index>& nodes, std::array<bool, 3> components = {true, true, true});
  /// Numbers the free components 0..numFree()-1 in node-major order; call after all constrain()s.
  void finalize();

  Index numNodes() const { return numNodes_; }
  Index numFree() const { return numFree_; }
  Index numConstrained() const { return 3 * numNodes_ - numFree_; }
  /// Equation of (node, component), or -1 when constrained.
  Index equation(Index node, int component) const { return equation_[3 * node + component]; }
  /// The same numbering as a one-copy transform (what the Assembler consumes).
  DofTransform transform() const;

private:
  Index numNodes_;
  Index numFree_ = 0;
  bool finalized_ = false;
  std::vector<Index> equation_;
};

}  // namespace cyclone::fe
