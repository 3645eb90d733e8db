// Verification: harmonic balance against time integration of the same system
// and element laws (Newmark, from rest, run until the response repeats).
// The first-harmonic amplitudes must agree up to the truncation of each method;
// the HB error is printed against H with its run time.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>

#include "cyclone/continuation/NewtonSolve.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/hbm/CubicSpring.hpp"
#include "cyclone/hbm/JenkinsElement.hpp"
#include "cyclone/hbm/TimeIntegration.hpp"

using namespace cyclone;

namespace {

// Newton at a fixed frequency from the linear solution (the solution is unique there).
Eigen::VectorXd solveAt(const hbm::HarmonicBalanceSystem& sys, double omega) {
  continuation::ContinuationProblem problem;
  problem.size = sys.numUnknowns();
  problem.residual = [&](const Eigen::VectorXd& X, double w, Eigen::VectorXd& R) { sys.residual(X, w, R, nullptr); };
  problem.jacobian = [&](const Eigen::VectorXd& X, double w, Eigen::MatrixXd& J) {
    Eigen::VectorXd R;
    sys.residual(X, w, R, &J);
  };
  Eigen::VectorXd X = sys.linearSolution(omega);
  const auto newton = continuation::solveNewton(problem, X, omega, 1e-12, 100);
  EXPECT_TRUE(newton.converged) << "harmonic balance did not converge at omega " << omega << " (residual "
                                << newton.residualNorm << ")";
  return X;
}

}  // namespace

TEST(HbmVsTimeIntegration, DuffingAwayFromTheFolds) {
  Eigen::MatrixXd M(1, 1), C(1, 1), K(1, 1);
  M << 1.0;
  C << 0.05;
  K << 1.0;
  for (double omega : {0.8, 1.6}) {
    hbm::HarmonicBalanceSystem sys(M, C, K, hbm::HarmonicSet::upTo(7), 64);
    sys.addElement(std::make_shared<hbm::CubicSpring>(0.1), Eigen::VectorXd::Ones(1));
    sys.addExcitation(0, 1, 0.18);
    const Eigen::VectorXd X = solveAt(sys, omega);
    Timer timer;
    const auto ti = hbm::integrateToSteadyState(sys, omega, Eigen::VectorXd::Zero(sys.numUnknowns()));
    ASSERT_TRUE(ti.converged) << "no steady state after " << ti.periods << " periods";
    const double a1 = sys.amplitude(X, 0, 1), t1 = sys.amplitude(ti.coefficients, 0, 1);
    const double a3 = sys.amplitude(X, 0, 3), t3 = sys.amplitude(ti.coefficients, 0, 3);
    std::printf("Duffing W = %.1f: |x1| HB %.8f, time integration %.8f (rel. diff %.1e); |x3| %.3e vs %.3e; "
                "%d periods, %.2f s\n", omega, a1, t1, std::abs(t1 / a1 - 1), a3, t3, ti.periods, timer.seconds());
    // Newmark with 1024 steps per period: phase error ~ (w dt)^2 / 12 ~ 3e-6.
    EXPECT_NEAR(t1 / a1, 1.0, 2e-5);
    EXPECT_NEAR(t3, a3, 2e-5 * a1);
  }
}

TEST(HbmVsTimeIntegration, JenkinsFrictionDamperConvergesInH) {
  // Two DOFs, a Jenkins friction element from DOF 0 to ground, forced on DOF 0.
  Eigen::MatrixXd M = Eigen::MatrixXd::Identity(2, 2), K(2, 2);
  K << 2.0, -1.0, -1.0, 1.0;
  const Eigen::MatrixXd C = 0.01 * K;
  const double omega = 0.7;
  auto build = [&](int H, int samples) {
    hbm::HarmonicBalanceSystem sys(M, C, K, hbm::HarmonicSet::upTo(H), samples);
    sys.addElement(std::make_shared<hbm::JenkinsElement>(1.0, 0.05), Eigen::Vector2d(1.0, 0.0));
    sys.addExcitation(0, 1, 0.2);
    return sys;
  };
  auto reference = build(3, 2048);
  const auto ti = hbm::integrateToSteadyState(reference, omega, Eigen::VectorXd::Zero(reference.numUnknowns()));
  ASSERT_TRUE(ti.converged);
  const double t1 = reference.amplitude(ti.coefficients, 1, 1);
  std::printf("Jenkins damper, W = %.1f: time integration |x1| of DOF 1 = %.7f (%d periods)\n", omega, t1, ti.periods);
  std::vector<double> errors;
  for (int H : {1, 3, 7, 15}) {
    Timer timer;
    auto sys = build(H, 2048);
    const Eigen::VectorXd X = solveAt(sys, omega);
    const double a1 = sys.amplitude(X, 1, 1);
    errors.push_back(std::abs(a1 / t1 - 1));
    std::printf("  H = %2d: |x1| %.7f, relative difference %.2e, %.2f s\n", H, a1, errors.back(), timer.seconds());
  }
  EXPECT_LT(errors.back(), 1e-3);
  EXPECT_LT(errors.back(), errors.front());
}
