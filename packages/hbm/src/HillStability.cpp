#include "cyclone/hbm/HillStability.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
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

HillProblemSize hillProblemSize(const HarmonicBalanceSystem& sys, const HillOptions& options) {
  if (!sys.isReceptance()) return {2 * sys.numDofs() * sys.numCoefficients(), true};
  const int unknowns = 2 * receptanceModalCoordinates(sys);
  return {unknowns, unknowns <= options.denseUpTo};
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
  // Companion form of the problem in mu = lambda / s: [0 I; -D2^-1 J / s^2, -D2^-1 D1 / s],
  // s = sqrt(|J| / |D2|) the size of the exponents' imaginary parts. Unscaled, a stiff
  // system's companion matrix has a norm of |J| / |D2| (1e12 for K = 1e12, M = 1), and the
  // eigenvalues' rounding, about its norm times 1e-16, exceeded the damping's real part
  // (-0.025 came out as +5.5: "unstable", issue 49 probe); scaled, the matrix is of order
  // one and the rounding of lambda about s times 1e-16.
  const auto lu = D2.partialPivLu();
  if (!(lu.rcond() > kSingularMass)) throw InputError("stability", "Hill's method needs an invertible mass matrix");
  const double normJ = J.norm(), normD2 = D2.norm();
  const double s = normJ > 0 && normD2 > 0 ? std::sqrt(normJ / normD2) : 1.0;
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(2 * m, 2 * m);
  A.block(0, m, m, m).setIdentity();
  A.block(m, 0, m, m) = -lu.solve(J) / (s * s);
  A.block(m, m, m, m) = -lu.solve(D1) / s;
  Eigen::EigenSolver<Eigen::MatrixXd> es(A, false);
  const Eigen::VectorXcd all = s * es.eigenvalues();
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
