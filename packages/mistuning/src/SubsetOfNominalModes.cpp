#include "cyclone/mistuning/SubsetOfNominalModes.hpp"

#include <cmath>
#include <complex>
#include <numeric>
#include <string>

#include "cyclone/core/Error.hpp"

namespace cyclone::mistuning {

using cd = std::complex<double>;

Eigen::MatrixXcd subsetOfNominalModesStiffness(const std::vector<int>& modesPerPhase,
                                               const Eigen::MatrixXcd& bladeProjection,
                                               const std::vector<double>& deviations) {
  const int N = int(modesPerPhase.size());
  if (int(deviations.size()) != N)
    throw InputError("mistuning/youngs_modulus_factors", "has " + std::to_string(deviations.size()) +
                                                             " entries; the ring has " + std::to_string(N) + " blades");
  const int m = std::accumulate(modesPerPhase.begin(), modesPerPhase.end(), 0);
  if (bladeProjection.rows() != m || bladeProjection.cols() != m)
    throw Error("subsetOfNominalModesStiffness: the blade projection is not " + std::to_string(m) + " square");
  // The pattern's spatial harmonics D_d = (1/N) sum_j delta_j e^{i 2 pi d j / N}: block (p, q)
  // takes D_{(p - q) mod N}.
  std::vector<cd> D(N, cd(0, 0));
  for (int d = 0; d < N; ++d)
    for (int j = 0; j < N; ++j) {
      if (deviations[j] == 0) continue;
      const double a = 2 * M_PI * double((long(d) * j) % N) / N;
      D[d] += deviations[j] / N * cd(std::cos(a), std::sin(a));
    }
  std::vector<int> first(N, 0);
  for (int p = 1; p < N; ++p) first[p] = first[p - 1] + modesPerPhase[p - 1];
  Eigen::MatrixXcd dK = Eigen::MatrixXcd::Zero(m, m);
  for (int p = 0; p < N; ++p)
    for (int q = 0; q < N; ++q) {
      const cd s = D[((p - q) % N + N) % N];
      if (s == cd(0, 0)) continue;
      dK.block(first[p], first[q], modesPerPhase[p], modesPerPhase[q]) =
          s * bladeProjection.block(first[p], first[q], modesPerPhase[p], modesPerPhase[q]);
    }
  return dK;
}

MistunedRingReceptance::MistunedRingReceptance(hbm::ModalRealization tuned, Eigen::MatrixXcd dK)
    : tuned_(std::move(tuned)), dK_(std::move(dK)) {
  const int m = tuned_.numModes();
  if (dK_.rows() != m || dK_.cols() != m)
    throw Error("MistunedRingReceptance: dK is " + std::to_string(dK_.rows()) + " x " + std::to_string(dK_.cols()) +
                " for " + std::to_string(m) + " modes");
  if (tuned_.viscous.size() != m) tuned_.viscous = Eigen::VectorXd::Zero(m);
  Eigen::MatrixXcd S = dK_;
  S.diagonal() += tuned_.eigenvalues.cast<cd>();
  const Eigen::MatrixXcd A = tuned_.R + tuned_.U * S.partialPivLu().solve(tuned_.V.transpose());
  mean_ = A.real();
}

void MistunedRingReceptance::requirePhaseZero(long phaseIndex) const {
  if (phaseIndex != 0)
    throw Error("the mistuned ring is not cyclic: asked for phase index " + std::to_string(phaseIndex));
}

Eigen::MatrixXcd MistunedRingReceptance::compliance(double frequency, long phaseIndex) const {
  requirePhaseZero(phaseIndex);
  const cd damped(1, tuned_.lossFactor);
  Eigen::MatrixXcd S = damped * dK_;
  for (int i = 0; i < tuned_.numModes(); ++i)
    S(i, i) += damped * tuned_.eigenvalues(i) + cd(0, frequency * tuned_.viscous(i)) - frequency * frequency;
  return tuned_.R / damped + tuned_.U * S.partialPivLu().solve(tuned_.V.transpose());
}

MistunedRingReceptance::Modes MistunedRingReceptance::modes() const {
  Eigen::MatrixXcd S = 0.5 * (dK_ + dK_.adjoint());
  S.diagonal() += tuned_.eigenvalues.cast<cd>();
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXcd> eig(S);
  return {eig.eigenvalues(), tuned_.U * eig.eigenvectors()};
}

}  // namespace cyclone::mistuning
