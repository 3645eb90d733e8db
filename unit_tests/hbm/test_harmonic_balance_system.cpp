// The assembled harmonic balance residual: its linear part against the
// frequency-domain closed form, and its full Jacobian against finite differences.
#include <gtest/gtest.h>

#include <memory>

#include "cyclone/hbm/CubicSpring.hpp"
#include "cyclone/hbm/HarmonicBalanceSystem.hpp"
#include "cyclone/hbm/JenkinsElement.hpp"
#include "cyclone/hbm/QuadraticDamper.hpp"

using namespace cyclone;

namespace {
hbm::HarmonicBalanceSystem twoDofSystem() {
  Eigen::MatrixXd M(2, 2), C(2, 2), K(2, 2);
  M << 1.0, 0.0, 0.0, 0.5;
  K << 3.0, -1.0, -1.0, 2.0;
  C = 0.02 * K;
  hbm::HarmonicBalanceSystem s(M, C, K, hbm::HarmonicSet::upTo(3), 64);
  s.addExcitation(0, 1, 0.3, 0.1);
  s.addElement(std::make_shared<hbm::CubicSpring>(0.7), Eigen::Vector2d(1.0, 0.0));
  s.addElement(std::make_shared<hbm::JenkinsElement>(2.0, 0.4), Eigen::Vector2d(1.0, -1.0));
  s.addElement(std::make_shared<hbm::QuadraticDamper>(0.05), Eigen::Vector2d(0.0, 1.0));
  return s;
}
}  // namespace

TEST(HarmonicBalanceSystem, LinearPartIsTheDynamicStiffness) {
  // Without elements, X = Z^{-1} F gives x(t) whose complex amplitude at harmonic 1
  // equals (K - w^2 M + i w C)^{-1} f with f = a - i b for a cos + b sin.
  Eigen::MatrixXd M(2, 2), C(2, 2), K(2, 2);
  M << 1.0, 0.0, 0.0, 0.5;
  K << 3.0, -1.0, -1.0, 2.0;
  C = 0.02 * K;
  hbm::HarmonicBalanceSystem s(M, C, K, hbm::HarmonicSet::upTo(2), 16);
  s.addExcitation(0, 1, 0.3, 0.1);
  const double w = 1.3;
  const Eigen::VectorXd X = s.linearSolution(w);
  const Eigen::MatrixXcd Zc = (K - w * w * M).cast<std::complex<double>>() + std::complex<double>(0, w) * C;
  Eigen::VectorXcd f(2);
  f << std::complex<double>(0.3, -0.1), 0;
  const Eigen::VectorXcd q = Zc.partialPivLu().solve(f);  // x = Re(q e^{iwt}) = Re q cos - Im q sin
  const int nc = s.numCoefficients();
  const auto& H = s.aft().harmonics();
  for (int d = 0; d < 2; ++d) {
    EXPECT_NEAR(X(d * nc + H.cosIndex(1)), q(d).real(), 1e-14);
    EXPECT_NEAR(X(d * nc + H.sinIndex(1)), -q(d).imag(), 1e-14);
    EXPECT_NEAR(X(d * nc + H.cosIndex(2)), 0.0, 1e-15);
  }
}

TEST(HarmonicBalanceSystem, JacobianMatchesFiniteDifferences) {
  const auto s = twoDofSystem();
  Eigen::VectorXd X = 0.8 * Eigen::VectorXd::Random(s.numUnknowns());
  const double w = 1.1;
  Eigen::VectorXd R;
  Eigen::MatrixXd J;
  s.residual(X, w, R, &J);
  Eigen::MatrixXd fd(s.numUnknowns(), s.numUnknowns());
  const double h = 1e-7;
  for (int j = 0; j < s.numUnknowns(); ++j) {
    Eigen::VectorXd Xp = X, Xm = X, Rp, Rm;
    Xp(j) += h, Xm(j) -= h;
    s.residual(Xp, w, Rp, nullptr);
    s.residual(Xm, w, Rm, nullptr);
    fd.col(j) = (Rp - Rm) / (2 * h);
  }
  EXPECT_LT((fd - J).norm() / J.norm(), 1e-6);
}
