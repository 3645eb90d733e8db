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
      const Eigen::MatrixXcd direct = projectedDirectly(w, p), modal = ModalStiffness::compliance(*r, w);
      if (!((direct - modal).norm() <= 1e-10 * direct.norm())) out.usable = false;
    }
    out.r = std::move(*r);
    if (out.usable) out.stiffness = ModalStiffness(out.r);
  }
  return projected_.emplace(p, std::move(out)).first->second;
}

Eigen::MatrixXcd ProjectedReceptance::compliance(double frequency, long p) const {
  if (frequency > 0) {
    const Projected& pr = projected(p);
    if (pr.usable) return ModalStiffness::compliance(pr.r, frequency);
  }
  return projectedDirectly(frequency, p);
}

Eigen::MatrixXcd ProjectedReceptance::dynamicStiffness(double frequency, long p) const {
  if (frequency > 0) {
    const Projected& pr = projected(p);
    if (pr.stiffness.usable()) return pr.stiffness(frequency);
  }
  return ReceptanceModel::dynamicStiffness(frequency, p);
}

const ModalStiffness* ProjectedReceptance::modalStiffness(long p) const {
  const Projected& pr = projected(p);
  return pr.stiffness.usable() ? &pr.stiffness : nullptr;
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
