#include "cyclone/rom/SectorReceptance.hpp"

#include <Eigen/SVD>
#include <complex>
#include <vector>
#include <string>

#include "cyclone/core/Error.hpp"
#include "cyclone/rom/HybridFrfModel.hpp"

namespace cyclone::rom {

namespace {
int copies(int sectors, int k) { return (k == 0 || 2 * k == sectors) ? 1 : 2; }
}  // namespace

SectorReceptance::SectorReceptance(int sectors, std::map<int, std::shared_ptr<const ComplianceModel>> models)
    : sectors_(sectors), models_(std::move(models)) {
  if (sectors < 2) throw InputError("reduced model", "a cyclic sector needs N >= 2, got " + std::to_string(sectors));
  if (models_.empty()) throw InputError("reduced model", "no nodal diameter's model given");
  for (const auto& [k, m] : models_) {
    if (k < 0 || 2 * k > sectors)
      throw InputError("reduced model", "nodal diameter " + std::to_string(k) + " is outside 0.." +
                                            std::to_string(sectors / 2));
    if (!m) throw InputError("reduced model", "nodal diameter " + std::to_string(k) + " has no model");
    const int c = copies(sectors, k);
    if (m->size() % (3 * c) != 0)
      throw InputError("reduced model", "nodal diameter " + std::to_string(k) + ": size " + std::to_string(m->size()) +
                                            " is not 3 x nodes x " + std::to_string(c) + " copies");
    const int n = int(m->size()) / c;
    if (dofs_ != 0 && n != dofs_)
      throw InputError("reduced model", "nodal diameters retain different DOFs (" + std::to_string(dofs_) + " and " +
                                            std::to_string(n) + ")");
    dofs_ = n;
  }
}

std::pair<int, int> SectorReceptance::nodalDiameter(int sectors, long phaseIndex) {
  const long p = ((phaseIndex % sectors) + sectors) % sectors;
  const long k = (sectors - p) % sectors;  // the FE phase: neighbour = e^{+j 2 pi k / N} this sector
  if (2 * k <= sectors) return {int(k), +1};
  return {int(p), -1};
}

const ComplianceModel& SectorReceptance::model(int k) const {
  const auto it = models_.find(k);
  if (it == models_.end())
    throw InputError("reduced model", "no model for nodal diameter " + std::to_string(k) +
                                          ", which the engine order and harmonics need");
  return *it->second;
}

Eigen::MatrixXcd SectorReceptance::compliance(double frequency, long phaseIndex) const {
  const auto [k, sign] = nodalDiameter(sectors_, phaseIndex);
  const Eigen::MatrixXcd A = model(k).compliance(frequency);
  if (copies(sectors_, k) == 1) return A;
  const int n = dofs_;
  return A.topLeftCorner(n, n) + std::complex<double>(0, sign) * A.bottomLeftCorner(n, n);
}

// The dynamic stiffness by Woodbury's identity over the phase's modal realization
// (hbm::ModalStiffness: checked there against the plain inverse, unusable where the
// constant part R is ill conditioned or absent, e.g. a modal truncation).
const hbm::ModalStiffness& SectorReceptance::stiffness(long key) const {
  if (auto it = stiffness_.find(key); it != stiffness_.end()) return it->second;
  const auto r = modalRealization(key);
  return stiffness_.emplace(key, r ? hbm::ModalStiffness(*r) : hbm::ModalStiffness()).first->second;
}

Eigen::MatrixXcd SectorReceptance::dynamicStiffness(double frequency, long phaseIndex) const {
  const long key = ((phaseIndex % sectors_) + sectors_) % sectors_;
  const hbm::ModalStiffness& z = stiffness(key);
  if (frequency > 0 && z.usable()) return z(frequency);
  return ReceptanceModel::dynamicStiffness(frequency, phaseIndex);
}

std::optional<hbm::ModalRealization> SectorReceptance::modalRealization(long phaseIndex) const {
  const long key = ((phaseIndex % sectors_) + sectors_) % sectors_;
  if (auto it = realizations_.find(key); it != realizations_.end()) return it->second;
  const auto [k, sign] = nodalDiameter(sectors_, key);
  const HybridFrfModel* modal = model(k).modalForm();
  std::optional<hbm::ModalRealization> out;
  if (modal) {
    using cd = std::complex<double>;
    const int n = dofs_;
    const bool pair = copies(sectors_, k) == 2;
    const cd si(0, sign);
    const double eta = modal->lossFactor();
    const auto& modes = modal->modes();
    hbm::ModalRealization r;
    r.lossFactor = eta;
    // residualCompliance() is R / (1 + i eta); the realization holds the undamped R.
    const Eigen::MatrixXcd R2 = modal->residualCompliance() * cd(1, eta);
    r.R = pair ? Eigen::MatrixXcd(R2.topLeftCorner(n, n) + si * R2.bottomLeftCorner(n, n)) : R2;
    const Eigen::MatrixXd& phi = modes.shapes;
    if (!pair) {
      r.U = phi.cast<cd>();
      r.V = r.U;
      r.eigenvalues = Eigen::Map<const Eigen::VectorXd>(modes.eigenvalues.data(), modes.numModes());
    } else {
      // Group the copies of equal natural frequency; each group's U0 V0^T has rank <= its
      // size: from the QR of U0 and a small SVD, keep its nonzero singular directions.
      const Eigen::MatrixXcd U0 = phi.topRows(n).cast<cd>() + si * phi.bottomRows(n).cast<cd>();
      const Eigen::MatrixXcd V0 = phi.topRows(n).cast<cd>();
      std::vector<Eigen::VectorXcd> us, vs;
      std::vector<double> ls;
      for (int j = 0; j < modes.numModes();) {
        int e = j + 1;
        while (e < modes.numModes() && std::abs(modes.eigenvalues[e] - modes.eigenvalues[j]) <=
                                           1e-6 * std::max(std::abs(modes.eigenvalues[j]), 1e-300))
          ++e;
        const int g = e - j;
        double l = 0;
        for (int i = j; i < e; ++i) l += modes.eigenvalues[i] / g;
        const Eigen::HouseholderQR<Eigen::MatrixXcd> qr(U0.middleCols(j, g));
        const Eigen::MatrixXcd Q = qr.householderQ() * Eigen::MatrixXcd::Identity(n, g);
        const Eigen::MatrixXcd small = Q.adjoint() * U0.middleCols(j, g) * V0.middleCols(j, g).transpose();  // g x n
        const Eigen::JacobiSVD<Eigen::MatrixXcd> svd(small, Eigen::ComputeThinU | Eigen::ComputeThinV);
        const auto& sv = svd.singularValues();
        for (int i = 0; i < sv.size(); ++i) {
          if (!(sv(i) > 1e-8 * sv(0))) continue;
          us.push_back(Q * svd.matrixU().col(i) * sv(i));
          vs.push_back(svd.matrixV().col(i).conjugate());
          ls.push_back(l);
        }
        j = e;
      }
      const int m = int(ls.size());
      r.U.resize(n, m), r.V.resize(n, m), r.eigenvalues.resize(m);
      for (int i = 0; i < m; ++i) r.U.col(i) = us[i], r.V.col(i) = vs[i], r.eigenvalues(i) = ls[i];
    }
    r.viscous = Eigen::VectorXd::Zero(r.numModes());
    out = std::move(r);
  }
  return realizations_.emplace(key, std::move(out)).first->second;
}

Eigen::MatrixXd SectorReceptance::meanCompliance() const { return model(0).zeroFrequencyCompliance(); }

Eigen::MatrixXcd SectorReceptance::staticCompliance(long phaseIndex) const {
  const auto [k, sign] = nodalDiameter(sectors_, phaseIndex);
  const Eigen::MatrixXd A = model(k).zeroFrequencyCompliance();
  if (copies(sectors_, k) == 1) return A.cast<std::complex<double>>();
  const int n = dofs_;
  return A.topLeftCorner(n, n).cast<std::complex<double>>() +
         std::complex<double>(0, sign) * A.bottomLeftCorner(n, n).cast<std::complex<double>>();
}

}  // namespace cyclone::rom
