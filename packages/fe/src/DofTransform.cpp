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
    }
  // Masters: a DOF that carries the unknown alone with coefficient 1. Preferred on a
  // node whose three components all do (the node that owns the unknowns): a cyclic
  // right-face node can carry one unknown of its left partner alone too (k = 0, the
  // axial component), and must not take it. Copy 0 DOFs in physical order come
  // first, so masters are copy-0 DOFs when possible.
  const std::size_t perCopy = std::size_t(numNodes_) * 3;
  auto alone = [&](std::size_t s) { return building_[s].size() == 1 && building_[s][0].coefficient == 1.0; };
  for (int pass = 0; pass < 2; ++pass)
    for (std::size_t s = 0; s < building_.size(); ++s) {
      const std::size_t first = s - s % 3;  // component 0 of the same node and copy
      if (!alone(s) || (pass == 0 && !(alone(first) && alone(first + 1) && alone(first + 2)))) continue;
      const long long eq = building_[s][0].equation;
      if (master_[eq] >= 0) continue;
      master_[eq] = (long long)(s % perCopy);
      masterCopy_[eq] = int(s / perCopy);
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

std::vector<std::array<double, 3>> DofTransform::nodalField(const double* x, int copy) const {
  std::vector<std::array<double, 3>> field(numNodes_, {0.0, 0.0, 0.0});
  for (Index node = 0; node < numNodes_; ++node)
    for (int d = 0; d < 3; ++d)
      for (const auto& t : terms(node, d, copy)) field[node][d] += t.coefficient * x[t.equation];
  return field;
}

}  // namespace cyclone::fe
