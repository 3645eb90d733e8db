#include "cyclone/fe/DofMap.hpp"

#include "cyclone/core/Error.hpp"

namespace cyclone::fe {

DofMap::DofMap(Index numNodes) : numNodes_(numNodes), equation_(3 * numNodes, 0) {}

void DofMap::constrain(const std::vector<Index>& nodes, std::array<bool, 3> components) {
  if (finalized_) throw Error("DofMap::constrain called after finalize");
  for (Index n : nodes) {
    if (n < 0 || n >= numNodes_) throw Error("DofMap: constrained node index " + std::to_string(n) + " out of range");
    for (int d = 0; d < 3; ++d)
      if (components[d]) equation_[3 * n + d] = -1;
  }
}

void DofMap::finalize() {
  numFree_ = 0;
  for (auto& eq : equation_) eq = (eq < 0) ? -1 : numFree_++;
  finalized_ = true;
}

DofTransform DofMap::transform() const {
  if (!finalized_) throw Error("DofMap::transform called before finalize");
  DofTransform t(numNodes_, 1);
  for (Index n = 0; n < numNodes_; ++n)
    for (int d = 0; d < 3; ++d)
      if (equation_[3 * n + d] >= 0) t.set(n, d, 0, {{equation_[3 * n + d], 1.0}});
  t.finalize(numFree_);
  return t;
}

}  // namespace cyclone::fe
