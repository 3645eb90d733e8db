#pragma once
// The linear part of a dynamic-stiffness receptance system (HarmonicBalanceSystem) at one
// frequency, harmonic by harmonic, where the model gives each harmonic's stiffness in
// Woodbury's parts (ModalStiffness: Z_h = Z0_p - G_p C(h w) Hv_p, p the harmonic's phase
// index): only the m x m cores C are made per frequency, and a product with every
// harmonic's block reads each phase's n x n constant part once for all the harmonics on
// that phase (a matrix product over their columns) instead of forming a dense block per
// harmonic and streaming each. With EO 3 on 24 sectors, 30 harmonics fall on 8 phases:
// what a GMRES product reads of the linear part drops about fourfold (issue 47: H = 30
// on the default disc). The residual keeps the formed blocks
// (HarmonicBalanceSystem::applyHarmonicOperator says why).
#include <Eigen/Dense>
#include <vector>

#include "cyclone/hbm/ModalStiffness.hpp"

namespace cyclone::hbm {

class ModalStiffnessBlocks {
public:
  /// parts[i]: harmonic index i's Woodbury parts (nullptr: not covered, e.g. the mean,
  /// which the caller applies itself); frequencies[i]: its frequency h omega (> 0 where
  /// covered). The parts must outlive this (the receptance model owns them).
  ModalStiffnessBlocks(std::vector<const ModalStiffness*> parts, const std::vector<double>& frequencies);
  std::size_t size() const { return parts_.size(); }
  bool covers(std::size_t i) const { return parts_[i] != nullptr; }
  /// Y.col(i) = Z_i X.col(i) for every covered index i: X and Y are n x size(), column i
  /// harmonic index i's complex coefficients (c - i s) of every DOF; other columns of Y
  /// are left as they are. Not for concurrent calls (work storage kept between calls).
  void apply(const Eigen::MatrixXcd& X, Eigen::MatrixXcd& Y) const;

private:
  struct Group {
    const ModalStiffness* parts;
    std::vector<int> indices;  // the harmonic indices on these parts (one phase)
  };
  std::vector<const ModalStiffness*> parts_;
  std::vector<Eigen::MatrixXcd> cores_;  // per covered index: C(h omega)
  std::vector<Group> groups_;
  mutable Eigen::MatrixXcd x_, y_, t_, u_;  // apply()'s work: no allocation once grown
};

}  // namespace cyclone::hbm
