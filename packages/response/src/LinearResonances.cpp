#include "cyclone/response/LinearResonances.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

namespace cyclone::response {

namespace {

// sqrt of the positive generalized eigenvalues of (K, M), appended to `out`.
void naturalFrequencies(const Eigen::MatrixXd& K, const Eigen::MatrixXd& M, std::vector<double>& out) {
  if (!((K - K.transpose()).norm() <= 1e-12 * std::max(K.norm(), 1e-300))) return;
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(K, M, Eigen::EigenvaluesOnly);
  if (es.info() != Eigen::Success) return;
  for (Eigen::Index i = 0; i < es.eigenvalues().size(); ++i)
    if (es.eigenvalues()(i) > 0 && std::isfinite(es.eigenvalues()(i))) out.push_back(std::sqrt(es.eigenvalues()(i)));
}

}  // namespace

std::vector<double> linearResonances(const hbm::HarmonicBalanceSystem& system) {
  std::vector<double> out;
  if (system.isReceptance() || system.isCyclic()) return out;
  const Eigen::MatrixXd& M = system.M();
  const Eigen::LLT<Eigen::MatrixXd> positive(M);
  if (positive.info() != Eigen::Success || !((M - M.transpose()).norm() <= 1e-12 * M.norm())) return out;
  naturalFrequencies(system.K(), M, out);
  if (!system.elements().empty() && system.aft().harmonics().contains(1)) {
    // The elements' stiffness at rest: their Jacobian's harmonic-1 cosine block at X = 0.
    const int n = system.numDofs(), nc = system.numCoefficients(), c1 = system.aft().harmonics().cosIndex(1);
    Eigen::VectorXd F;
    Eigen::MatrixXd J;
    system.nonlinearForces(Eigen::VectorXd::Zero(system.numUnknowns()), 1.0, F, &J);
    Eigen::MatrixXd Kr(n, n);
    for (int a = 0; a < n; ++a)
      for (int b = 0; b < n; ++b) Kr(a, b) = J(a * nc + c1, b * nc + c1);
    if (Kr.allFinite() && Kr.norm() > 0) naturalFrequencies(system.K() + 0.5 * (Kr + Kr.transpose()), M, out);
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace cyclone::response
