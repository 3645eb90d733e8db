#include "cyclone/mistuning/RingReceptance.hpp"

#include <cmath>
#include <complex>
#include <string>
#include <vector>

#include "cyclone/core/Error.hpp"

namespace cyclone::mistuning {

using cd = std::complex<double>;

RingReceptance::RingReceptance(std::shared_ptr<const hbm::ReceptanceModel> sector) : sector_(std::move(sector)) {
  if (!sector_) throw InputError("ring", "no sector model given");
  N_ = sector_->sectors(), n_ = sector_->numDofs();
  if (N_ < 2) throw InputError("ring", "the sector model is not cyclic (N = " + std::to_string(N_) + ")");
  if (n_ < 1) throw InputError("ring", "the sector model has no DOFs");
  std::vector<Eigen::MatrixXcd> statics(N_);
  for (int p = 0; p < N_; ++p) {
    try {
      statics[p] = sector_->staticCompliance(p);
    } catch (const InputError& e) {
      throw InputError(e.where(), "phase index " + std::to_string(p) + ": " + e.problem() +
                                      " (the ring of sectors needs every phase index 0.." + std::to_string(N_ - 1) +
                                      ")");
    }
    if (statics[p].rows() != n_ || statics[p].cols() != n_)
      throw InputError("ring", "phase index " + std::to_string(p) + "'s static compliance is not " +
                                   std::to_string(n_) + " square");
  }
  // Real up to rounding: the phases p and N - p are complex conjugates for a real structure.
  mean_ = ringMatrix(statics).real();
}

Eigen::MatrixXcd RingReceptance::ringMatrix(const std::vector<Eigen::MatrixXcd>& phases) {
  const int N = int(phases.size());
  if (N == 0) return {};
  const Eigen::Index n = phases[0].rows();
  // The N distinct blocks C_d = (1/N) sum_p B_p e^{-i 2 pi p d / N}, block (j, k) = C_{(j - k) mod N}.
  std::vector<Eigen::MatrixXcd> C(N, Eigen::MatrixXcd::Zero(n, n));
  for (int d = 0; d < N; ++d)
    for (int p = 0; p < N; ++p) {
      const double a = -2 * M_PI * double((long(p) * d) % N) / N;
      C[d].noalias() += cd(std::cos(a) / N, std::sin(a) / N) * phases[p];
    }
  Eigen::MatrixXcd out(N * n, N * n);
  for (int j = 0; j < N; ++j)
    for (int k = 0; k < N; ++k) out.block(j * n, k * n, n, n) = C[((j - k) % N + N) % N];
  return out;
}

void RingReceptance::requirePhaseZero(long phaseIndex) const {
  if (phaseIndex != 0)
    throw Error("the ring of sectors is not cyclic: asked for phase index " + std::to_string(phaseIndex));
}

Eigen::MatrixXcd RingReceptance::compliance(double frequency, long phaseIndex) const {
  requirePhaseZero(phaseIndex);
  std::vector<Eigen::MatrixXcd> phases(N_);
  for (int p = 0; p < N_; ++p) phases[p] = sector_->compliance(frequency, p);
  return ringMatrix(phases);
}

Eigen::MatrixXcd RingReceptance::dynamicStiffness(double frequency, long phaseIndex) const {
  requirePhaseZero(phaseIndex);
  std::vector<Eigen::MatrixXcd> phases(N_);
  for (int p = 0; p < N_; ++p) phases[p] = sector_->dynamicStiffness(frequency, p);
  return ringMatrix(phases);
}

std::optional<hbm::ModalRealization> RingReceptance::modalRealization(long phaseIndex) const {
  requirePhaseZero(phaseIndex);
  if (realized_) return realization_;
  realized_ = true;
  std::vector<hbm::ModalRealization> r;
  for (int p = 0; p < N_; ++p) {
    auto rp = sector_->modalRealization(p);
    if (!rp || rp->lossFactor != (r.empty() ? rp->lossFactor : r[0].lossFactor)) return realization_;
    r.push_back(std::move(*rp));
  }
  hbm::ModalRealization out;
  out.lossFactor = r[0].lossFactor;
  int m = 0;
  for (const auto& rp : r) m += rp.numModes();
  std::vector<Eigen::MatrixXcd> Rs(N_);
  for (int p = 0; p < N_; ++p) Rs[p] = r[p].R;
  out.R = ringMatrix(Rs);
  out.U.resize(N_ * n_, m), out.V.resize(N_ * n_, m), out.eigenvalues.resize(m), out.viscous.resize(m);
  const double scale = 1.0 / std::sqrt(double(N_));
  int c = 0;
  for (int p = 0; p < N_; ++p) {
    const int mp = r[p].numModes();
    for (int j = 0; j < N_; ++j) {
      const double a = 2 * M_PI * double((long(p) * j) % N_) / N_;
      out.U.block(j * n_, c, n_, mp) = cd(std::cos(a) * scale, -std::sin(a) * scale) * r[p].U;
      out.V.block(j * n_, c, n_, mp) = cd(std::cos(a) * scale, std::sin(a) * scale) * r[p].V;
    }
    out.eigenvalues.segment(c, mp) = r[p].eigenvalues;
    out.viscous.segment(c, mp) = r[p].viscous.size() == mp ? r[p].viscous : Eigen::VectorXd::Zero(mp);
    c += mp;
  }
  realization_ = std::move(out);
  return realization_;
}

}  // namespace cyclone::mistuning
