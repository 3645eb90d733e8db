#pragma once
// The map from physical DOFs to the unknowns actually solved for:
//   u(node, component, copy) = sum over terms of coefficient * x[equation].
// A plain constrained model has one copy and one term (or none, when fixed)
// per DOF. A cyclic sector at nodal diameter k has one or two copies (the real
// and imaginary parts, for 0 < k < N/2), and its right-face DOFs are rotated,
// phase-shifted combinations of the left-face ones. Operators assemble as
// sum over copies of T_c^T K T_c, element by element.
#include <array>
#include <cstdint>
#include <vector>

#include "cyclone/mesh/Mesh.hpp"

namespace cyclone::fe {

using mesh::Index;

class DofTransform {
public:
  struct Term {
    long long equation;
    double coefficient;
  };
  struct Range {
    const Term* first;
    const Term* last;
    const Term* begin() const { return first; }
    const Term* end() const { return last; }
    bool empty() const { return first == last; }
  };

  DofTransform(Index numNodes, int copies);

  /// Building: the terms of (node, component, copy); default none (fixed at zero).
  void set(Index node, int component, int copy, std::vector<Term> terms);
  /// Building: the number of unknowns; then finalize() packs the terms.
  void finalize(long long numEquations);

  Index numNodes() const { return numNodes_; }
  int copies() const { return copies_; }
  long long numEquations() const { return numEquations_; }
  Range terms(Index node, int component, int copy) const {
    const std::size_t slot = this->slot(node, component, copy);
    return {terms_.data() + offsets_[slot], terms_.data() + offsets_[slot + 1]};
  }
  /// The physical field (numNodes x 3, zeros on fixed components) of copy `copy`
  /// for the unknowns x (numEquations values).
  std::vector<std::array<double, 3>> nodalField(const double* x, int copy) const;
  /// A physical DOF that carries each unknown with coefficient 1 (its "master"),
  /// as node*3 + component for copy `masterCopy(eq)`; -1 if none.
  const std::vector<long long>& masterDof() const { return master_; }
  /// The copy of each unknown's master DOF (0 or 1).
  const std::vector<int>& masterCopy() const { return masterCopy_; }
  /// True when every node has 0 or 3 unknowns per copy, numbered consecutively
  /// (3 x copies per node): what MueLu's block aggregation needs.
  bool blockedByNode() const { return blocked_; }

private:
  std::size_t slot(Index node, int component, int copy) const {
    return (std::size_t(copy) * numNodes_ + node) * 3 + component;
  }
  Index numNodes_;
  int copies_;
  long long numEquations_ = 0;
  std::vector<std::vector<Term>> building_;
  std::vector<std::size_t> offsets_;
  std::vector<Term> terms_;
  std::vector<long long> master_;
  std::vector<int> masterCopy_;
  bool blocked_ = false;
};

}  // namespace cyclone::fe
