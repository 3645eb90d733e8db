#include "cyclone/hbm/FullRingSystem.hpp"

#include "cyclone/core/Error.hpp"

namespace cyclone::hbm {

std::unique_ptr<HarmonicBalanceSystem> expandToFullRing(const HarmonicBalanceSystem& s) {
  if (!s.isCyclic()) throw InputError("full ring", "the system is not cyclic");
  const int N = s.cyclic().sectors, n = s.numDofs();
  const auto& cyc = s.cyclic();
  auto ring = [&](const Eigen::MatrixXd& A, const Eigen::MatrixXd& Anext) {
    Eigen::MatrixXd R = Eigen::MatrixXd::Zero(N * n, N * n);
    for (int j = 0; j < N; ++j) {
      const int k = (j + 1) % N;
      R.block(j * n, j * n, n, n) += A;
      R.block(j * n, k * n, n, n) += Anext;
      R.block(k * n, j * n, n, n) += Anext.transpose();
    }
    return R;
  };
  auto full = std::make_unique<HarmonicBalanceSystem>(ring(s.M(), cyc.Mnext), ring(s.C(), cyc.Cnext),
                                                      ring(s.K(), cyc.Knext), s.aft().harmonics(),
                                                      s.aft().numSamples());
  for (const auto& c : s.elements())
    for (int j = 0; j < N; ++j) {
      Eigen::MatrixXd W = Eigen::MatrixXd::Zero(N * n, c.W.cols());
      W.middleRows(j * n, n) += c.W;
      if (c.Wnext.size()) W.middleRows(((j + 1) % N) * n, n) += c.Wnext;
      full->addElement(c.element, W);
    }
  // Excitation: sector j's is sector 0's delayed (S^j F); static loads the same on every sector.
  full->addExcitationCoefficients(ringCoefficients(s, s.excitation()));
  full->addStaticLoadCoefficients(ringCoefficients(s, s.staticLoad()));
  return full;
}

Eigen::VectorXd ringCoefficients(const HarmonicBalanceSystem& s, const Eigen::VectorXd& X) {
  if (!s.isCyclic()) throw InputError("full ring", "the system is not cyclic");
  const int N = s.cyclic().sectors, n = s.numDofs(), nc = s.numCoefficients();
  if (X.size() != n * nc) throw InputError("full ring", "coefficient vector of the wrong size");
  Eigen::VectorXd out(N * n * nc);
  Eigen::MatrixXd Xj = Eigen::Map<const Eigen::MatrixXd>(X.data(), nc, n);
  for (int j = 0; j < N; ++j) {
    Eigen::Map<Eigen::MatrixXd>(out.data() + j * n * nc, nc, n) = Xj;
    Xj = s.nextSectorMap() * Xj;
  }
  return out;
}

}  // namespace cyclone::hbm
