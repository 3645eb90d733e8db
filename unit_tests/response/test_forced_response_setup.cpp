// response::continuationProblem on small matrix systems: the residual rows divided by the
// forces acting on them (the mean rows by the static loads, the others by the dynamic
// excitation), so that the continuation's tolerance is relative and a large preload
// neither swamps a small excitation nor is held to its absolute accuracy; the mean and
// the oscillating coefficients in separate scale groups; the Jacobian (dense and as
// blocks) the derivative of that scaled residual.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "cyclone/hbm/CubicSpring.hpp"
#include "cyclone/hbm/HarmonicBalanceSystem.hpp"
#include "cyclone/response/ForcedResponseSetup.hpp"

using namespace cyclone;

namespace {

// Two DOFs, harmonics 0..3, a cubic spring between them; 1e6 N pressing DOF 0, 10 N at
// the first harmonic on DOF 1.
std::unique_ptr<hbm::HarmonicBalanceSystem> pressedPair() {
  Eigen::MatrixXd M = Eigen::MatrixXd::Identity(2, 2), K(2, 2), C;
  K << 2, -1, -1, 2;
  C = 0.02 * K;
  auto hb = std::make_unique<hbm::HarmonicBalanceSystem>(M, C, K, hbm::HarmonicSet::upTo(3), 64);
  hb->addElement(std::make_shared<hbm::CubicSpring>(0.3), Eigen::Vector2d(1, -1));
  hb->addStaticLoad(0, 1e6);
  hb->addExcitation(1, 1, 10.0);
  return hb;
}

}  // namespace

TEST(ForcedResponseSetup, ResidualRowsAreRelativeToTheForcesOnThem) {
  const auto hb = pressedPair();
  const auto& H = hb->aft().harmonics();
  const int nc = hb->numCoefficients();
  const double omega = 1.3;
  const auto problem = response::continuationProblem(*hb, response::ForcedResponseSetup::Parameter::Omega, omega, 1.0);
  Eigen::VectorXd R;
  problem.residual(Eigen::VectorXd::Zero(hb->numUnknowns()), omega, R);
  // At rest the residual is minus the loads: each the whole of its group's norm.
  for (int a = 0; a < 2; ++a)
    for (int k = 0; k < nc; ++k) {
      const double expected = (a == 0 && k == H.cosIndex(0)) || (a == 1 && k == H.cosIndex(1)) ? -1.0 : 0.0;
      EXPECT_NEAR(R(a * nc + k), expected, 1e-15) << "DOF " << a << ", coefficient " << k;
    }
  // The unscaled residual at a state, divided row by row: 1e6 on the mean rows, 10 on the others.
  Eigen::VectorXd X = Eigen::VectorXd::LinSpaced(hb->numUnknowns(), -0.3, 0.4), raw;
  hb->residual(X, omega, raw, nullptr);
  problem.residual(X, omega, R);
  for (int a = 0; a < 2; ++a)
    for (int k = 0; k < nc; ++k) {
      const double scale = k == H.cosIndex(0) ? 1e6 : 10.0;
      EXPECT_NEAR(R(a * nc + k), raw(a * nc + k) / scale, 1e-15 * std::abs(raw(a * nc + k)) + 1e-300);
    }
}

TEST(ForcedResponseSetup, MeanAndOscillationAreSeparateScaleGroups) {
  const auto hb = pressedPair();
  const auto& H = hb->aft().harmonics();
  const int nc = hb->numCoefficients();
  const auto problem = response::continuationProblem(*hb, response::ForcedResponseSetup::Parameter::Omega, 1.0, 1.0);
  ASSERT_EQ(int(problem.scaleGroups.size()), hb->numUnknowns());
  for (int a = 0; a < 2; ++a)
    for (int k = 0; k < nc; ++k) EXPECT_EQ(problem.scaleGroups[std::size_t(a * nc + k)], k == H.cosIndex(0) ? 0 : 1);
}

TEST(ForcedResponseSetup, JacobianIsTheScaledResidualsDerivative) {
  const auto hb = pressedPair();
  const double omega = 1.3;
  const auto problem = response::continuationProblem(*hb, response::ForcedResponseSetup::Parameter::Omega, omega, 1.0);
  const Eigen::VectorXd X = Eigen::VectorXd::LinSpaced(hb->numUnknowns(), -0.3, 0.4);
  Eigen::MatrixXd J;
  problem.jacobian(X, omega, J);
  // Central differences of the scaled residual, column by column.
  Eigen::MatrixXd D(J.rows(), J.cols());
  const double h = 1e-6;
  for (int j = 0; j < J.cols(); ++j) {
    Eigen::VectorXd plus = X, minus = X, Rp, Rm;
    plus(j) += h, minus(j) -= h;
    problem.residual(plus, omega, Rp);
    problem.residual(minus, omega, Rm);
    D.col(j) = (Rp - Rm) / (2 * h);
  }
  EXPECT_LT((J - D).norm(), 1e-7 * J.norm());
  // The blocks' product is the dense Jacobian's.
  ASSERT_TRUE(bool(problem.jacobianOperator));
  const auto op = problem.jacobianOperator(X, omega);
  const Eigen::VectorXd v = Eigen::VectorXd::LinSpaced(hb->numUnknowns(), 1.0, -2.0);
  Eigen::VectorXd Jv;
  op->apply(v, Jv);
  EXPECT_LT((Jv - J * v).norm(), 1e-12 * (J * v).norm());
}
