#include "cyclone/hbm/ModalStiffnessBlocks.hpp"

#include "cyclone/core/Error.hpp"

namespace cyclone::hbm {

ModalStiffnessBlocks::ModalStiffnessBlocks(std::vector<const ModalStiffness*> parts, const std::vector<double>& frequencies)
    : parts_(std::move(parts)), cores_(parts_.size()) {
  if (frequencies.size() != parts_.size()) throw Error("ModalStiffnessBlocks: a frequency per harmonic index is needed");
  for (std::size_t i = 0; i < parts_.size(); ++i) {
    if (!parts_[i]) continue;
    if (!(frequencies[i] > 0)) throw Error("ModalStiffnessBlocks: Woodbury's parts hold for frequencies above zero");
    parts_[i]->core(frequencies[i], cores_[i]);
    auto group = groups_.begin();
    while (group != groups_.end() && group->parts != parts_[i]) ++group;
    if (group == groups_.end()) group = groups_.insert(groups_.end(), Group{parts_[i], {}});
    group->indices.push_back(int(i));
  }
}

// Per phase: Y = Z0 X - G [C_j (Hv X)_j]_j over the phase's columns X.
void ModalStiffnessBlocks::apply(const Eigen::MatrixXcd& X, Eigen::MatrixXcd& Y) const {
  if (X.cols() != Eigen::Index(parts_.size()) || Y.rows() != X.rows() || Y.cols() != X.cols())
    throw Error("ModalStiffnessBlocks::apply: coefficients of the wrong shape");
  for (const Group& g : groups_) {
    const Eigen::Index k = Eigen::Index(g.indices.size());
    x_.resize(X.rows(), k);
    for (Eigen::Index j = 0; j < k; ++j) x_.col(j) = X.col(g.indices[std::size_t(j)]);
    // Column by column: Eigen's complex matrix product packs Z0 at every call, which for a
    // few columns costs more than reading it once per column from the cache.
    y_.resize(X.rows(), k);
    t_.resize(g.parts->Hv().rows(), k);
    u_.resize(t_.rows(), k);
    for (Eigen::Index j = 0; j < k; ++j) {
      y_.col(j).noalias() = g.parts->constantPart() * x_.col(j);
      t_.col(j).noalias() = g.parts->Hv() * x_.col(j);
      u_.col(j).noalias() = cores_[std::size_t(g.indices[std::size_t(j)])] * t_.col(j);
      y_.col(j).noalias() -= g.parts->G() * u_.col(j);
    }
    for (Eigen::Index j = 0; j < k; ++j) Y.col(g.indices[std::size_t(j)]) = y_.col(j);
  }
}

}  // namespace cyclone::hbm
