#include "cyclone/hbm/ProjectedReceptance.hpp"

#include <cmath>
#include <complex>
#include <string>

#include "cyclone/core/Error.hpp"

namespace cyclone::hbm {

ProjectedReceptance::ProjectedReceptance(std::shared_ptr<const ReceptanceModel> base, Eigen::MatrixXd T,
                                         Eigen::MatrixXd Tnext)
    : base_(std::move(base)), T_(std::move(T)), Tnext_(std::move(Tnext)) {
  if (!base_) throw InputError("receptance", "no base model to project");
  const int n = base_->numDofs();
  if (T_.rows() < 1 || T_.cols() != n)
    throw InputError("receptance", "the projection needs at least one row of " + std::to_string(n) + " columns");
  if (Tnext_.size() == 0) Tnext_ = Eigen::MatrixXd::Zero(T_.rows(), n);
  if (Tnext_.rows() != T_.rows() || Tnext_.cols() != n)
    throw InputError("receptance", "the next-sector projection must have the shape of T");
  if (base_->sectors() < 2 && Tnext_.norm() > 0)
    throw InputError("receptance", "a projection onto the next sector needs a cyclic model");
}

Eigen::MatrixXcd ProjectedReceptance::transform(long p) const {
  const int N = std::max(base_->sectors(), 1);
  const double a = 2 * M_PI * double(((p % N) + N) % N) / double(N);
  return T_.cast<std::complex<double>>() + std::complex<double>(std::cos(a), -std::sin(a)) * Tnext_;
}

Eigen::MatrixXcd ProjectedReceptance::projectedDirectly(double frequency, long p) const {
  const Eigen::MatrixXcd Tp = transform(p);
  return Tp * base_->compliance(frequency, p) * Tp.adjoint();
}

namespace {

// A(w) = R / (1 + i eta) + U diag(1 / ((1 + i eta) l_j + i c_j w - w^2)) V^T (ReceptanceModel.hpp).
Eigen::MatrixXcd fromModes(const ModalRealization& r, double w) {
  const std::complex<double> structural(1.0, r.lossFactor);
  Eigen::VectorXcd d(r.numModes());
  for (int j = 0; j < r.numModes(); ++j) {
    const double c = r.viscous.size() != 0 ? r.viscous(j) : 0.0;
    d(j) = 1.0 / (structural * r.eigenvalues(j) + std::complex<double>(-w * w, c * w));
  }
  Eigen::MatrixXcd A = r.R / structural;
  A.noalias() += r.U * d.asDiagonal() * r.V.transpose();
  return A;
}

std::complex<double> structuralFactor(const ModalRealization& r) { return {1.0, r.lossFactor}; }

// The modal weights' inverses D^-1: (1 + i eta) l_j + i c_j w - w^2.
Eigen::VectorXcd inverseWeights(const ModalRealization& r, double w) {
  Eigen::VectorXcd d(r.numModes());
  for (int j = 0; j < r.numModes(); ++j) {
    const double c = r.viscous.size() != 0 ? r.viscous(j) : 0.0;
    d(j) = structuralFactor(r) * r.eigenvalues(j) + std::complex<double>(-w * w, c * w);
  }
  return d;
}

Eigen::MatrixXcd woodburyStiffness(const ModalRealization& r, const Eigen::MatrixXcd& Rinv, const Eigen::MatrixXcd& G,
                                   const Eigen::MatrixXcd& Hv, const Eigen::MatrixXcd& K, double w) {
  const std::complex<double> s = structuralFactor(r);
  Eigen::MatrixXcd M = s * K;
  M.diagonal() += inverseWeights(r, w);
  Eigen::MatrixXcd Z = s * Rinv;
  Z.noalias() -= (s * s) * (G * M.partialPivLu().solve(Hv));
  return Z;
}

// Woodbury's pieces where R is well conditioned and the identity reproduces the plain
// inverse at two frequencies between the modes (1e-8: the residual part of a hybrid
// model can be ill conditioned, and then the inverse is taken plainly).
bool prepareWoodbury(const ModalRealization& r, Eigen::MatrixXcd& Rinv, Eigen::MatrixXcd& G, Eigen::MatrixXcd& Hv,
                     Eigen::MatrixXcd& K) {
  const Eigen::PartialPivLU<Eigen::MatrixXcd> lu(r.R);
  if (!(lu.rcond() > 1e-12)) return false;
  Rinv = lu.inverse();
  G = Rinv * r.U;
  Hv = r.V.transpose() * Rinv;
  K = r.V.transpose() * G;
  const double top = std::sqrt(r.eigenvalues.cwiseAbs().maxCoeff());
  for (double w : {0.37 * top, 1.13 * top}) {
    const Eigen::MatrixXcd plain = fromModes(r, w).inverse();
    const Eigen::MatrixXcd fast = woodburyStiffness(r, Rinv, G, Hv, K, w);
    if (!plain.allFinite() || !((fast - plain).norm() <= 1e-8 * plain.norm())) return false;
  }
  return true;
}

}  // namespace

const ProjectedReceptance::Projected& ProjectedReceptance::projected(long p) const {
  auto it = projected_.find(p);
  if (it != projected_.end()) return it->second;
  Projected out;
  auto r = projectedRealization(p);
  out.hasRealization = r.has_value();
  if (r && r->numModes() == 0) out.r = std::move(*r);
  if (r && r->numModes() > 0) {
    // The check at two frequencies between the modes (not on one: a pole there says nothing).
    const double top = std::sqrt(r->eigenvalues.cwiseAbs().maxCoeff());
    out.usable = true;
    for (double w : {0.37 * top, 1.13 * top}) {
      const Eigen::MatrixXcd direct = projectedDirectly(w, p), modal = fromModes(*r, w);
      if (!((direct - modal).norm() <= 1e-10 * direct.norm())) out.usable = false;
    }
    out.r = std::move(*r);
    if (out.usable) out.woodbury = prepareWoodbury(out.r, out.Rinv, out.G, out.Hv, out.K);
  }
  return projected_.emplace(p, std::move(out)).first->second;
}

Eigen::MatrixXcd ProjectedReceptance::compliance(double frequency, long p) const {
  if (frequency > 0) {
    const Projected& pr = projected(p);
    if (pr.usable) return fromModes(pr.r, frequency);
  }
  return projectedDirectly(frequency, p);
}

Eigen::MatrixXcd ProjectedReceptance::dynamicStiffness(double frequency, long p) const {
  if (frequency > 0) {
    const Projected& pr = projected(p);
    if (pr.woodbury) return woodburyStiffness(pr.r, pr.Rinv, pr.G, pr.Hv, pr.K, frequency);
  }
  return ReceptanceModel::dynamicStiffness(frequency, p);
}

Eigen::MatrixXd ProjectedReceptance::meanCompliance() const {
  const Eigen::MatrixXd T0 = T_ + Tnext_;
  return T0 * base_->meanCompliance() * T0.transpose();
}

std::optional<ModalRealization> ProjectedReceptance::modalRealization(long p) const {
  const Projected& pr = projected(p);
  if (!pr.hasRealization) return std::nullopt;
  return pr.r;
}

std::optional<ModalRealization> ProjectedReceptance::projectedRealization(long p) const {
  auto r = base_->modalRealization(p);
  if (!r) return r;
  const Eigen::MatrixXcd Tp = transform(p);
  r->R = Tp * r->R * Tp.adjoint();
  r->U = Tp * r->U;
  r->V = Tp.conjugate() * r->V;
  return r;
}

}  // namespace cyclone::hbm
