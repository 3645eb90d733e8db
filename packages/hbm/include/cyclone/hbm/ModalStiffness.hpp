#pragma once
// The dynamic stiffness of a modal realization (ReceptanceModel.hpp),
//   A(w) = R / s + U D(w) V^T,  s = 1 + i eta,  D_j = 1 / (s l_j + i c_j w - w^2),
// by Woodbury's identity, Z = A^-1 = s R^-1 - s^2 G (D^-1 + s K)^-1 Hv with G = R^-1 U,
// Hv = V^T R^-1, K = V^T R^-1 U formed once: an m x m solve and a rank-m update per
// frequency (m modes) instead of an n x n inverse. A hybrid model's R can be ill
// conditioned: the identity is taken only where R's LU is well conditioned and it
// reproduces the plain inverse of A at two frequencies between the modes (1e-8).
#include <Eigen/Dense>

#include "cyclone/hbm/ReceptanceModel.hpp"

namespace cyclone::hbm {

class ModalStiffness {
public:
  ModalStiffness() = default;
  explicit ModalStiffness(const ModalRealization& r);
  /// Whether the identity holds (else the caller inverts A itself).
  bool usable() const { return usable_; }
  /// Z(w) for w > 0 (only when usable()).
  Eigen::MatrixXcd operator()(double w) const;
  /// Z(w) = Z0 - G C(w) Hv in its parts (only when usable()): the constant Z0 = s R^-1
  /// (n x n), G and Hv (n x m, m x n), and the m x m core C(w) = s^2 (D^-1 + s K)^-1 made
  /// into C (its storage kept). ModalStiffnessBlocks applies Z without forming it.
  const Eigen::MatrixXcd& constantPart() const { return Z0_; }
  const Eigen::MatrixXcd& G() const { return G_; }
  const Eigen::MatrixXcd& Hv() const { return Hv_; }
  int numModes() const { return r_.numModes(); }
  void core(double w, Eigen::MatrixXcd& C) const;
  /// A(w) from the realization, for w > 0.
  static Eigen::MatrixXcd compliance(const ModalRealization& r, double w);

private:
  ModalRealization r_;
  Eigen::MatrixXcd Rinv_, G_, Hv_, K_, Z0_;
  bool usable_ = false;
};

}  // namespace cyclone::hbm
