#pragma once
// A receptance model given by a modal realization, as a hybrid reduced model's: shared by
// the tests of Woodbury's dynamic stiffness (ProjectedReceptance, ModalStiffnessBlocks).
#include <Eigen/Dense>
#include <complex>
#include <random>

#include "cyclone/hbm/ReceptanceModel.hpp"

namespace cyclone::test_support {

// n DOFs, m modes: A(w) = R / (1 + i eta) + U diag(1 / ((1 + i eta) l_j + i c_j w - w^2)) V^T,
// U = V = real mode shapes (a symmetric model), R symmetric positive definite (or zero).
class ModalTestModel final : public hbm::ReceptanceModel {
public:
  ModalTestModel(int n, int m, int sectors, bool residual) : sectors_(sectors) {
    std::mt19937 rng(7);
    std::normal_distribution<double> g;
    r_.U.resize(n, m);
    for (int i = 0; i < r_.U.size(); ++i) r_.U.data()[i] = g(rng);
    r_.V = r_.U;
    r_.eigenvalues = Eigen::VectorXd::LinSpaced(m, 1.0, 40.0).array().square();
    r_.viscous = 0.002 * r_.eigenvalues.cwiseSqrt();
    r_.lossFactor = 0.006;
    Eigen::MatrixXd B(n, n);
    for (int i = 0; i < B.size(); ++i) B.data()[i] = g(rng);
    r_.R = residual ? Eigen::MatrixXcd((1e-4 * (B * B.transpose() + n * Eigen::MatrixXd::Identity(n, n))).cast<std::complex<double>>())
                    : Eigen::MatrixXcd::Zero(n, n);
  }
  int numDofs() const override { return int(r_.R.rows()); }
  int sectors() const override { return sectors_; }
  Eigen::MatrixXcd compliance(double w, long) const override {
    const std::complex<double> s(1.0, r_.lossFactor);
    Eigen::VectorXcd d(r_.numModes());
    for (int j = 0; j < r_.numModes(); ++j) d(j) = 1.0 / (s * r_.eigenvalues(j) + std::complex<double>(-w * w, r_.viscous(j) * w));
    return r_.R / s + r_.U * d.asDiagonal() * r_.V.transpose();
  }
  Eigen::MatrixXd meanCompliance() const override { return compliance(0.0, 0).real(); }
  std::optional<hbm::ModalRealization> modalRealization(long) const override { return r_; }

private:
  hbm::ModalRealization r_;
  int sectors_;
};

}  // namespace cyclone::test_support
