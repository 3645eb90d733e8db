// DenseLu (LAPACK's dgetrf/dgetrs) against the definition: A x = b to rounding, for
// sizes across the blocked code's block boundaries, and a singular matrix's solve
// not finite (the correctors test allFinite to cut a step).
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "cyclone/continuation/DenseLu.hpp"

using cyclone::continuation::DenseLu;

TEST(DenseLu, SolvesToRoundingAtSizesAcrossTheBlocks) {
  for (int n : {1, 2, 7, 64, 65, 301}) {
    const Eigen::MatrixXd A = Eigen::MatrixXd::Random(n, n) + n * Eigen::MatrixXd::Identity(n, n) * 0.1;
    const Eigen::VectorXd b = Eigen::VectorXd::Random(n);
    const Eigen::VectorXd x = DenseLu(A).solve(b);
    const double scale = A.norm() * x.norm() + b.norm();
    EXPECT_LT((A * x - b).norm(), 1e-13 * scale) << "n = " << n;
  }
}

TEST(DenseLu, PivotsWhereTheLeadingEntryIsZero) {
  Eigen::MatrixXd A(2, 2);
  A << 0, 1, 1, 0;  // no LU without a row exchange
  const Eigen::VectorXd x = DenseLu(A).solve(Eigen::Vector2d(3, 5));
  EXPECT_DOUBLE_EQ(x(0), 5);
  EXPECT_DOUBLE_EQ(x(1), 3);
}

TEST(DenseLu, ASingularMatrixGivesNoFiniteSolution) {
  Eigen::MatrixXd A(3, 3);
  A << 1, 2, 3, 2, 4, 6, 0, 1, 1;  // row 2 = 2 row 1
  EXPECT_FALSE(DenseLu(A).solve(Eigen::Vector3d(1, 2, 3)).allFinite());
}

TEST(DenseLu, RejectsANonSquareMatrixAndAMismatchedRightHandSide) {
  EXPECT_THROW(DenseLu(Eigen::MatrixXd::Ones(2, 3)), std::invalid_argument);
  EXPECT_THROW(DenseLu(Eigen::MatrixXd::Identity(2, 2)).solve(Eigen::VectorXd::Ones(3)), std::invalid_argument);
}
