#include "cyclone/hbm/ModalReceptance.hpp"

#include <cmath>
#include <cstdio>
#include <complex>
#include <string>

#include "cyclone/core/Error.hpp"
#include "cyclone/hbm/ModalStiffness.hpp"

#include <Eigen/Eigenvalues>

namespace cyclone::hbm {

namespace {
long folded(long p, int sectors) { return ((p % sectors) + sectors) % sectors; }

ModalRealization conjugated(ModalRealization r) {
  r.R = r.R.conjugate();
  r.U = r.U.conjugate();
  r.V = r.V.conjugate();
  return r;
}
}  // namespace

ModalReceptance::ModalReceptance(int sectors, std::map<long, ModalRealization> realizations) : sectors_(sectors) {
  if (sectors < 1) throw InputError("receptance", "sectors must be >= 1, got " + std::to_string(sectors));
  if (realizations.empty()) throw InputError("receptance", "a modal receptance needs at least one phase's modes");
  for (auto& [p, r] : realizations) {
    const long q = folded(p, sectors);
    const int n = int(r.U.rows());
    if (dofs_ == 0) dofs_ = n;
    if (n != dofs_ || r.V.rows() != n || r.U.cols() != r.numModes() || r.V.cols() != r.numModes() ||
        (r.R.size() != 0 && (r.R.rows() != n || r.R.cols() != n)) ||
        (r.viscous.size() != 0 && r.viscous.size() != r.numModes()))
      throw InputError("receptance", "the modal realization of phase " + std::to_string(p) + " has inconsistent sizes");
    if (r.R.size() == 0) r.R = Eigen::MatrixXcd::Zero(n, n);
    if (r.viscous.size() == 0) r.viscous = Eigen::VectorXd::Zero(r.numModes());
    byPhase_[q] = r;
  }
  // The conjugate phases the caller left out.
  std::map<long, ModalRealization> added;
  for (const auto& [p, r] : byPhase_) {
    const long q = folded(sectors_ - p, sectors_);
    if (!byPhase_.count(q)) added.emplace(q, conjugated(r));
  }
  byPhase_.insert(added.begin(), added.end());
}

bool ModalReceptance::hasPhase(long p) const { return byPhase_.count(folded(p, sectors_)) > 0; }

const ModalRealization& ModalReceptance::realization(long p) const {
  const auto it = byPhase_.find(folded(p, sectors_));
  if (it == byPhase_.end())
    throw InputError("receptance", "the modal model has no modes for phase index " + std::to_string(p));
  return it->second;
}

Eigen::MatrixXcd ModalReceptance::compliance(double frequency, long p) const {
  return ModalStiffness::compliance(realization(p), frequency);
}

Eigen::MatrixXd ModalReceptance::meanCompliance() const {
  const ModalRealization& r = realization(0);
  Eigen::MatrixXcd A = r.R;
  A.noalias() += r.U * r.eigenvalues.cast<std::complex<double>>().cwiseInverse().asDiagonal() * r.V.transpose();
  return A.real();
}

std::optional<ModalRealization> ModalReceptance::modalRealization(long p) const { return realization(p); }

std::shared_ptr<ModalReceptance> causalModalModel(const ReceptanceModel& model, const std::vector<long>& phases,
                                                  double residualFrequency) {
  if (!(residualFrequency >= 0)) throw InputError("receptance", "the residual modes' frequency must be >= 0");
  const int N = std::max(model.sectors(), 1);
  std::map<long, ModalRealization> byPhase;
  for (long p : phases) {
    const long q = folded(p, N);
    if (byPhase.count(q) || byPhase.count(folded(N - q, N))) continue;
    auto r = model.modalRealization(q);
    if (!r)
      throw InputError("receptance", "phase index " + std::to_string(q) +
                                         " has no modal form: a modal model needs the model's modes");
    const int n = int(r->U.rows()), m = r->numModes();
    Eigen::VectorXd viscous = r->viscous.size() ? r->viscous : Eigen::VectorXd::Zero(m);
    for (int j = 0; j < m; ++j) viscous(j) += r->lossFactor * std::sqrt(std::max(r->eigenvalues(j), 0.0));
    ModalRealization out;
    out.R = Eigen::MatrixXcd::Zero(n, n);
    out.U = r->U, out.V = r->V, out.eigenvalues = r->eigenvalues, out.viscous = viscous;
    if (residualFrequency > 0 && r->R.size() != 0 && r->R.norm() > 0) {
      const double size = r->R.norm();
      // A hybrid model's R is the static compliance less the modes' part: Hermitian to
      // the rounding of that difference (measured 1e-8..1e-7 on the default disc).
      const double skew = (r->R - r->R.adjoint()).norm() / size;
      if (skew > 1e-5) {
        char why[160];
        std::snprintf(why, sizeof why, "phase index %ld: the constant part is not Hermitian (%.1e)", q, skew);
        throw InputError("receptance", why);
      }
      const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXcd> es(0.5 * (r->R + r->R.adjoint()));
      const Eigen::VectorXd& s = es.eigenvalues();
      if (s.minCoeff() < -1e-8 * s.cwiseAbs().maxCoeff())
        throw InputError("receptance", "phase index " + std::to_string(q) + ": the constant part is not positive semi-definite");
      std::vector<int> kept;
      for (int k = 0; k < s.size(); ++k)
        if (s(k) > 1e-12 * s.maxCoeff()) kept.push_back(k);
      const int mk = int(kept.size());
      const double wr2 = residualFrequency * residualFrequency;
      out.U.conservativeResize(n, m + mk), out.V.conservativeResize(n, m + mk);
      out.eigenvalues.conservativeResize(m + mk), out.viscous.conservativeResize(m + mk);
      for (int i = 0; i < mk; ++i) {
        const int k = kept[std::size_t(i)];
        const double a = std::sqrt(s(k) * wr2);
        out.U.col(m + i) = a * es.eigenvectors().col(k);
        out.V.col(m + i) = a * es.eigenvectors().col(k).conjugate();
        out.eigenvalues(m + i) = wr2;
        out.viscous(m + i) = r->lossFactor * residualFrequency;
      }
    }
    byPhase.emplace(q, std::move(out));
  }
  return std::make_shared<ModalReceptance>(N, std::move(byPhase));
}

}  // namespace cyclone::hbm
