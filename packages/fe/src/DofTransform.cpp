#include "cyclone/fe/DofTransform.hpp"

#include "cyclone/core/Error.hpp"

namespace cyclone::fe {

DofTransform::DofTransform(Index numNodes, int copies)
    : numNodes_(numNodes), copies_(copies), building_(std::size_t(numNodes) * 3 * copies) {
  if (copies < 1 || copies > 2) throw Error("DofTransform: copies must be 1 or 2");
}

void DofTransform::set(Index node, int component, int copy, std::vector<Term> terms) {
  if (building_.empty()) throw Error("DofTransform::set after finalize");
  building_[slot(node, component, copy)] = std::move(terms);
}

void DofTransform::finalize(long long numEquations) {
  numEquations_ = numEquations;
  offsets_.assign(building_.size() + 1, 0);
  for (std::size_t s = 0; s < building_.size(); ++s) offsets_[s + 1] = offsets_[s] + building_[s].size();
  terms_.clear();
  terms_.reserve(offsets_.back());
  master_.assign(numEquations, -1);
  masterCopy_.assign(numEquations, 0);
  for (std::size_t s = 0; s < building_.size(); ++s)
    for (const auto& t : building_[s]) {
      if (t.equation < 0 || t.equation >= numEquations)
        throw Error("DofTransform: equation " + std::to_string(t.equation) + " out of range");
      terms_.push_back(t);
      // Copy 0 DOFs in physical order come first, so masters are copy-0 DOFs when possible.
      if (t.coefficient == 1.0 && building_[s].size() == 1 && master_[t.equation] < 0) {
        master_[t.equation] = (long long)(s % (std::size_t(numNodes_) * 3));
        masterCopy_[t.equation] = int(s / (std::size_t(numNodes_) * 3));
      }
    }
  // Blocked by node: unknowns come in runs of 3 x copies, each run one node's masters.
  blocked_ = numEquations % (3 * copies_) == 0;
  for (long long e = 0; blocked_ && e < numEquations; e += 3 * copies_)
    for (int i = 0; i < 3 * copies_; ++i)
      if (master_[e + i] < 0 || master_[e + i] / 3 != master_[e] / 3) {
        blocked_ = false;
        break;
      }
  building_.clear();
  building_.shrink_to_fit();
}

}  // namespace cyclone::fe
