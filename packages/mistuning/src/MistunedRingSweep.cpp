#include "cyclone/mistuning/MistunedRingSweep.hpp"

#include <cmath>
#include <string>

#include "cyclone/core/Error.hpp"
#include "cyclone/mistuning/SubsetOfNominalModes.hpp"

namespace cyclone::mistuning {

using cd = std::complex<double>;

MistunedRingSweep::MistunedRingSweep(const hbm::ModalRealization& tuned, int sectors, int sectorDofs,
                                     const std::vector<int>& modesPerPhase, const Eigen::MatrixXcd& bladeProjection,
                                     int engineOrder, int excitationDof, int responseDof, cd force)
    : N_(sectors), n_(sectorDofs), eo_(engineOrder), resp_(responseDof), eta_(tuned.lossFactor) {
  if (N_ < 2 || int(modesPerPhase.size()) != N_ || tuned.U.rows() != Eigen::Index(N_) * n_)
    throw Error("MistunedRingSweep: the realization has " + std::to_string(tuned.U.rows()) + " rows for " +
                std::to_string(N_) + " sectors of " + std::to_string(n_) + " DOFs");
  if (engineOrder < 0 || engineOrder >= N_)
    throw InputError("mistuning/engine_order", "must lie in 0.." + std::to_string(N_ - 1));
  if (excitationDof < 0 || excitationDof >= n_ || responseDof < 0 || responseDof >= n_)
    throw InputError("mistuning/excitation_dof", "must lie in 0.." + std::to_string(n_ - 1));
  const int m = tuned.numModes();
  l_ = tuned.eigenvalues;
  c_ = tuned.viscous.size() == m ? tuned.viscous : Eigen::VectorXd::Zero(m);
  viscous_ = c_.cwiseAbs().maxCoeff() > 0;
  f_ = Eigen::VectorXcd::Zero(Eigen::Index(N_) * n_);
  for (int j = 0; j < N_; ++j) {
    const double a = -2 * M_PI * double((long(eo_) * j) % N_) / N_;
    f_(Eigen::Index(j) * n_ + excitationDof) = force * cd(std::cos(a), std::sin(a));
  }
  const Eigen::VectorXcd Rf = tuned.R * f_;
  Ur_.resize(N_, m);
  r0_.resize(N_);
  for (int j = 0; j < N_; ++j) {
    Ur_.row(j) = tuned.U.row(Eigen::Index(j) * n_ + resp_);
    r0_(j) = Rf(Eigen::Index(j) * n_ + resp_);
  }
  g_ = tuned.V.transpose() * f_;
  B_.reserve(std::size_t(N_));
  for (int j = 0; j < N_; ++j) {
    std::vector<double> unit(std::size_t(N_), 0.0);
    unit[std::size_t(j)] = 1;
    B_.push_back(subsetOfNominalModesStiffness(modesPerPhase, bladeProjection, unit));
  }
}

Eigen::MatrixXcd MistunedRingSweep::stiffnessPerturbation(const std::vector<double>& delta) const {
  if (int(delta.size()) != N_)
    throw InputError("mistuning/youngs_modulus_factors", "has " + std::to_string(delta.size()) +
                                                             " entries; the ring has " + std::to_string(N_) + " blades");
  Eigen::MatrixXcd dK = Eigen::MatrixXcd::Zero(l_.size(), l_.size());
  for (int j = 0; j < N_; ++j)
    if (delta[std::size_t(j)] != 0) dK += delta[std::size_t(j)] * B_[std::size_t(j)];
  return dK;
}

Eigen::MatrixXcd MistunedRingSweep::responses(const std::vector<double>& delta,
                                              const std::vector<double>& omegas) const {
  const cd damped(1, eta_);
  Eigen::MatrixXcd H = stiffnessPerturbation(delta);
  H.diagonal() += l_.cast<cd>();
  Eigen::MatrixXcd X(N_, Eigen::Index(omegas.size()));
  const Eigen::VectorXcd r = r0_ / damped;
  if (!viscous_) {
    // (1 + i eta) H - w^2 I = Y ((1 + i eta) L - w^2) Y^H.
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXcd> eig(0.5 * (H + H.adjoint()));
    const Eigen::MatrixXcd UY = Ur_ * eig.eigenvectors();
    const Eigen::VectorXcd h = eig.eigenvectors().adjoint() * g_;
    Eigen::VectorXcd q(h.size());  // one per call, not per frequency
    for (std::size_t k = 0; k < omegas.size(); ++k) {
      const double w2 = omegas[k] * omegas[k];
      for (Eigen::Index i = 0; i < h.size(); ++i) q(i) = h(i) / (damped * eig.eigenvalues()(i) - w2);
      X.col(Eigen::Index(k)) = r + UY * q;
    }
    return X;
  }
  Eigen::MatrixXcd S(H.rows(), H.cols());
  Eigen::PartialPivLU<Eigen::MatrixXcd> lu(H.rows());
  for (std::size_t k = 0; k < omegas.size(); ++k) {
    const double w = omegas[k];
    S = damped * H;
    for (Eigen::Index i = 0; i < S.rows(); ++i) S(i, i) += cd(0, w * c_(i)) - w * w;
    lu.compute(S);
    X.col(Eigen::Index(k)) = r + Ur_ * lu.solve(g_);
  }
  return X;
}

BladePeaks MistunedRingSweep::peaks(const std::vector<double>& delta, const std::vector<double>& omegas) const {
  return bladePeaksOf(responses(delta, omegas), omegas);
}

}  // namespace cyclone::mistuning
