#include "cyclone/hbm/ModalStiffness.hpp"

#include <cmath>
#include <complex>

namespace cyclone::hbm {

namespace {

std::complex<double> structuralFactor(const ModalRealization& r) { return {1.0, r.lossFactor}; }

// D^-1: (1 + i eta) l_j + i c_j w - w^2.
Eigen::VectorXcd inverseWeights(const ModalRealization& r, double w) {
  Eigen::VectorXcd d(r.numModes());
  for (int j = 0; j < r.numModes(); ++j) {
    const double c = r.viscous.size() != 0 ? r.viscous(j) : 0.0;
    d(j) = structuralFactor(r) * r.eigenvalues(j) + std::complex<double>(-w * w, c * w);
  }
  return d;
}

}  // namespace

Eigen::MatrixXcd ModalStiffness::compliance(const ModalRealization& r, double w) {
  const std::complex<double> s = structuralFactor(r);
  Eigen::MatrixXcd A = r.R / s;
  A.noalias() += r.U * inverseWeights(r, w).cwiseInverse().asDiagonal() * r.V.transpose();
  return A;
}

ModalStiffness::ModalStiffness(const ModalRealization& r) : r_(r) {
  if (r.numModes() == 0) return;
  const Eigen::PartialPivLU<Eigen::MatrixXcd> lu(r.R);
  if (!(lu.rcond() > 1e-12)) return;
  Rinv_ = lu.inverse();
  G_ = Rinv_ * r.U;
  Hv_ = r.V.transpose() * Rinv_;
  K_ = r.V.transpose() * G_;
  Z0_ = structuralFactor(r) * Rinv_;
  usable_ = true;
  const double top = std::sqrt(r.eigenvalues.cwiseAbs().maxCoeff());
  for (double w : {0.37 * top, 1.13 * top}) {
    const Eigen::MatrixXcd plain = compliance(r, w).inverse();
    if (!plain.allFinite() || !(((*this)(w) - plain).norm() <= 1e-8 * plain.norm())) usable_ = false;
  }
}

Eigen::MatrixXcd ModalStiffness::operator()(double w) const {
  const std::complex<double> s = structuralFactor(r_);
  Eigen::MatrixXcd M = s * K_;
  M.diagonal() += inverseWeights(r_, w);
  Eigen::MatrixXcd Z = Z0_;
  Z.noalias() -= (s * s) * (G_ * M.partialPivLu().solve(Hv_));
  return Z;
}

void ModalStiffness::core(double w, Eigen::MatrixXcd& C) const {
  const std::complex<double> s = structuralFactor(r_);
  Eigen::MatrixXcd M = s * K_;
  M.diagonal() += inverseWeights(r_, w);
  C = (s * s) * M.partialPivLu().inverse();
}

}  // namespace cyclone::hbm
