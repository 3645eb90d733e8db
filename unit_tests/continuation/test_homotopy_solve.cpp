// The homotopy that switches added equations on (HomotopySolve.hpp), on a system
// where Newton from the carried guess stalls: x1 = 1 + 0.1 x2^2 (the "old" row, which
// the guess (1, 0) satisfies) and x2^3 - 2 x2 + 2 = 0 (the added row), whose Newton
// iteration from 0 falls into the spurious minimum of |F| at x2 = sqrt(2/3). The
// reference is the cubic's one real root by Cardano's formula.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "cyclone/continuation/HomotopySolve.hpp"

using namespace cyclone;

namespace {

continuation::ContinuationProblem stalledCubic() {
  continuation::ContinuationProblem p;
  p.size = 2;
  p.residual = [](const Eigen::VectorXd& x, double, Eigen::VectorXd& F) {
    F.resize(2);
    F << x(0) - 1 - 0.1 * x(1) * x(1), x(1) * x(1) * x(1) - 2 * x(1) + 2;
  };
  p.jacobian = [](const Eigen::VectorXd& x, double, Eigen::MatrixXd& J) {
    J.resize(2, 2);
    J << 1, -0.2 * x(1), 0, 3 * x(1) * x(1) - 2;
  };
  return p;
}

}  // namespace

TEST(HomotopySolve, PassesWhereNewtonFromTheCarriedGuessStalls) {
  const auto problem = stalledCubic();
  // Cardano: x^3 + p x + q = 0 with p = -2, q = 2 has one real root (discriminant > 0).
  const double p = -2, q = 2, d = std::sqrt(q * q / 4 + p * p * p / 27);
  const double root = std::cbrt(-q / 2 + d) + std::cbrt(-q / 2 - d);
  Eigen::VectorXd guess(2);
  guess << 1, 0;
  Eigen::VectorXd newton = guess;
  ASSERT_FALSE(continuation::solveNewton(problem, newton, 0.0, 1e-12, 100).converged)
      << "the case must stall plain Newton, or it tests nothing";
  Eigen::VectorXd x = guess;
  const auto r = continuation::solveByHomotopy(problem, x, 0.0, {1}, 1e-12);
  std::printf("Newton from the guess stalls at x2 = %.6f; the homotopy: %d points, x2 = %.15f (Cardano %.15f)\n",
              newton(1), r.points, x(1), root);
  EXPECT_TRUE(r.newton.converged) << r.reason;
  EXPECT_FALSE(r.blockStart) << "Newton on the cubic alone stalls as well: no block start";
  EXPECT_TRUE(r.byHomotopy);
  EXPECT_NEAR(x(1), root, 1e-12);
  EXPECT_NEAR(x(0), 1 + 0.1 * root * root, 1e-12);
}

TEST(HomotopySolve, NewtonAloneWhereItConverges) {
  const auto problem = stalledCubic();
  Eigen::VectorXd x(2);
  x << 1, -1.5;  // in the root's basin
  const auto r = continuation::solveByHomotopy(problem, x, 0.0, {1}, 1e-12);
  EXPECT_TRUE(r.newton.converged);
  EXPECT_FALSE(r.byHomotopy);
  EXPECT_EQ(r.points, 0);
}

// The block start: x1 - x2 = 0 (the old row, held by the guess (0, 0)) and
// x2 - 1 - x1 + x1^2 / 2 + x2^2 / 2 = 0 (the added row). At the guess the whole
// Jacobian [[1, -1], [-1, 1]] is singular, so plain Newton cannot step; the added row
// alone (x1 held at 0) is x2^2 / 2 + x2 - 1 = 0, solved by Newton to sqrt(3) - 1, and
// Newton on the whole from there reaches the root x1 = x2 = 1 (closed form: x1 = x2 = x
// with x^2 (1/2 + 1/2) = 1), not the other one at -1.
TEST(HomotopySolve, SolvesTheAddedRowsAloneFirst) {
  continuation::ContinuationProblem p;
  p.size = 2;
  p.residual = [](const Eigen::VectorXd& x, double, Eigen::VectorXd& F) {
    F.resize(2);
    F << x(0) - x(1), x(1) - 1 - x(0) + 0.5 * x(0) * x(0) + 0.5 * x(1) * x(1);
  };
  p.jacobian = [](const Eigen::VectorXd& x, double, Eigen::MatrixXd& J) {
    J.resize(2, 2);
    J << 1, -1, -1 + x(0), 1 + x(1);
  };
  Eigen::VectorXd plain = Eigen::VectorXd::Zero(2);
  ASSERT_FALSE(continuation::solveNewton(p, plain, 0.0, 1e-12, 30).converged)
      << "plain Newton must fail from the guess, or this tests nothing";
  Eigen::VectorXd x = Eigen::VectorXd::Zero(2);
  const auto r = continuation::solveByHomotopy(p, x, 0.0, {1}, 1e-12);
  std::printf("block start, then Newton: x = (%.15f, %.15f), homotopy %d\n", x(0), x(1), int(r.byHomotopy));
  EXPECT_TRUE(r.newton.converged) << r.reason;
  EXPECT_TRUE(r.blockStart);
  EXPECT_FALSE(r.byHomotopy);
  EXPECT_NEAR(x(0), 1.0, 1e-12);
  EXPECT_NEAR(x(1), 1.0, 1e-12);
}
