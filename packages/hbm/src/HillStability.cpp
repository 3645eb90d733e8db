#include "cyclone/hbm/HillStability.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <numeric>

#include "ReceptanceHill.hpp"
#include "cyclone/core/Error.hpp"

namespace cyclone::hbm {

namespace {
constexpr double kSingularMass = 1e-14;  // reciprocal condition number of D2 below which it is singular
}  // namespace

bool hillMassInvertible(const HarmonicBalanceSystem& sys) {
  if (sys.isReceptance()) return true;
  return sys.coefficientOperator(sys.M(), sys.cyclic().Mnext).partialPivLu().rcond() > kSingularMass;
}

FloquetExponents hillStability(const HarmonicBalanceSystem& sys, const Eigen::VectorXd& X, double omega,
                               const HillOptions& options) {
  for (const auto& c : sys.elements())
    if (c.element->usesVelocity())
      throw InputError("stability", "Hill's method with velocity-dependent elements is not supported yet");
  if (sys.isReceptance()) return receptanceHillStability(sys, X, omega, options);
  const int n = sys.numDofs(), nc = sys.numCoefficients(), m = n * nc;
  Eigen::VectorXd R;
  Eigen::MatrixXd J;
  sys.residual(X, omega, R, &J);
  // Per-DOF blocks of the time derivative; for a cyclic system the sector
  // matrices act through the next-sector coupling (perturbations of the same
  // travelling-wave form as the solution).
  Eigen::MatrixXd wD = Eigen::MatrixXd::Zero(m, m);
  for (int a = 0; a < n; ++a) wD.block(a * nc, a * nc, nc, nc) = omega * sys.aft().derivativeMatrix();
  const auto& cyc = sys.cyclic();
  const Eigen::MatrixXd D2 = sys.coefficientOperator(sys.M(), cyc.Mnext);
  const Eigen::MatrixXd D1 = 2 * D2 * wD + sys.coefficientOperator(sys.C(), cyc.Cnext);
  // Companion form: [0 I; -D2^-1 J, -D2^-1 D1].
  const auto lu = D2.partialPivLu();
  if (!(lu.rcond() > kSingularMass)) throw InputError("stability", "Hill's method needs an invertible mass matrix");
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(2 * m, 2 * m);
  A.block(0, m, m, m).setIdentity();
  A.block(m, 0, m, m) = -lu.solve(J);
  A.block(m, m, m, m) = -lu.solve(D1);
  Eigen::EigenSolver<Eigen::MatrixXd> es(A, false);
  const Eigen::VectorXcd all = es.eigenvalues();
  FloquetExponents out;
  out.all = all;
  std::vector<int> order(all.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int i, int j) { return std::abs(all(i).imag()) < std::abs(all(j).imag()); });
  out.exponents.resize(2 * n);
  for (int i = 0; i < 2 * n; ++i) out.exponents(i) = all(order[i]);
  std::sort(out.exponents.data(), out.exponents.data() + 2 * n,
            [](const std::complex<double>& a, const std::complex<double>& b) { return a.real() > b.real(); });
  out.maxRealPart = out.exponents(0).real();
  // Neutral directions (e.g. a phase shift of an autonomous part) sit at Re = 0 to round-off.
  out.stable = out.maxRealPart < 1e-8 * std::max(1.0, omega);
  return out;
}

}  // namespace cyclone::hbm
