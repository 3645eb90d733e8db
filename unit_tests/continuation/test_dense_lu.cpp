// DenseLu (LAPACK's dgetrf/dgetrs, or sgetrf with refinement in double) against the
// definition: A x = b to rounding, for sizes across the blocked code's block
// boundaries, and a singular matrix's solve not finite (the correctors test allFinite
// to cut a step). The mixed-precision path against the double one: the same solutions
// to rounding where single precision serves, and the double factorisation made where
// it does not (an ill-conditioned matrix, entries beyond single precision's range).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <cstdlib>

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

namespace {
// A matrix of condition number `cond` (singular values from 1 down to 1 / cond, evenly
// in the logarithm) between two random orthogonal matrices.
Eigen::MatrixXd withCondition(int n, double cond, unsigned seed) {
  std::srand(seed);
  const Eigen::HouseholderQR<Eigen::MatrixXd> qu(Eigen::MatrixXd::Random(n, n)), qv(Eigen::MatrixXd::Random(n, n));
  Eigen::VectorXd sigma(n);
  for (int i = 0; i < n; ++i) sigma(i) = std::pow(cond, -double(i) / std::max(n - 1, 1));
  const Eigen::MatrixXd U = qu.householderQ(), V = qv.householderQ();
  return U * sigma.asDiagonal() * V.transpose();
}
double backwardError(const Eigen::MatrixXd& A, const Eigen::VectorXd& x, const Eigen::VectorXd& b) {
  return (A * x - b).cwiseAbs().maxCoeff() /
         (A.cwiseAbs().rowwise().sum().maxCoeff() * x.cwiseAbs().maxCoeff());
}
}  // namespace

TEST(DenseLu, MixedPrecisionGivesTheDoubleSolutionToRounding) {
  const int n = 300;
  const Eigen::MatrixXd A = withCondition(n, 1e4, 3);
  const Eigen::VectorXd b = Eigen::VectorXd::Random(n);
  const DenseLu mixed(A, DenseLu::Precision::Mixed), plain(A, DenseLu::Precision::Double);
  for (bool transposed : {false, true}) {
    const Eigen::VectorXd x = transposed ? mixed.solveTransposed(b) : mixed.solve(b);
    const Eigen::VectorXd y = transposed ? plain.solveTransposed(b) : plain.solve(b);
    const Eigen::MatrixXd At = transposed ? Eigen::MatrixXd(A.transpose()) : A;
    // dsgesv's stopping test: the backward error of a double LU, eps sqrt(n).
    EXPECT_LT(backwardError(At, x, b), 2.2e-16 * std::sqrt(double(n))) << "transposed " << transposed;
    // Both backward stable: the solutions differ by cond x (their backward errors).
    EXPECT_LT((x - y).norm(), 1e4 * 1e-14 * y.norm()) << "transposed " << transposed;
  }
  EXPECT_TRUE(mixed.singlePrecisionFactors());
  EXPECT_EQ(mixed.doubleFallbacks(), 0);
  EXPECT_GT(mixed.refinementSteps(), 0);  // single precision alone is not the answer
}

TEST(DenseLu, MixedPrecisionFactorsInDoubleWhereSinglePrecisionCannotServe) {
  const int n = 250;
  const Eigen::VectorXd b = Eigen::VectorXd::Random(n);
  // cond 1e10: single precision's LU is no approximation of A^-1 and its refinement
  // cannot converge; the double LU's backward error is still eps-sized.
  const Eigen::MatrixXd A = withCondition(n, 1e10, 5);
  const DenseLu lu(A, DenseLu::Precision::Mixed);
  const Eigen::VectorXd x = lu.solve(b);
  EXPECT_EQ(lu.doubleFallbacks(), 1);
  EXPECT_LT(backwardError(A, x, b), 2.2e-16 * std::sqrt(double(n)));
  // Entries far beyond single precision's range (1e50) and below it (1e-50): scaled
  // before the conversion, so the single factors serve.
  for (double scale : {1e50, 1e-50}) {
    const Eigen::MatrixXd S = withCondition(n, 100, 7) * scale;
    const DenseLu s(S, DenseLu::Precision::Mixed);
    const Eigen::VectorXd y = s.solve(b);
    EXPECT_TRUE(s.singlePrecisionFactors()) << scale;
    EXPECT_LT(backwardError(S, y, b), 2.2e-16 * std::sqrt(double(n))) << scale;
  }
  // Exactly singular (a zero column: an exactly zero pivot in either precision): no
  // finite solution on the mixed path either.
  Eigen::MatrixXd Z = withCondition(n, 10, 9);
  Z.col(4).setZero();
  EXPECT_FALSE(DenseLu(Z, DenseLu::Precision::Mixed).solve(b).allFinite());
}

// Factors kept for a later matrix (a Newton corrector's next Jacobian): the solves with
// the new matrix iterate (GMRES preconditioned by the kept factors) to the same
// backward error as its own LU, in both precisions and both transposes.
TEST(DenseLu, KeptFactorsSolveANearbyMatrixToADoubleLusAccuracy) {
  for (const auto precision : {DenseLu::Precision::Mixed, DenseLu::Precision::Double}) {
    const int n = 300;
    const Eigen::MatrixXd A0 = withCondition(n, 1e3, 11);
    std::srand(12);
    // Entries of 1e-6 beside a smallest singular value of 1e-3: ||A0^-1 (A1 - A0)|| ~ 0.03.
    const Eigen::MatrixXd A1 = A0 + 1e-6 * Eigen::MatrixXd::Random(n, n);
    const Eigen::VectorXd b = Eigen::VectorXd::Random(n);
    DenseLu lu(A0, precision);
    Eigen::MatrixXd taken = A1;
    ASSERT_TRUE(lu.reuseFactorsFor(taken));
    EXPECT_TRUE(lu.factorsAreStale());
    for (bool transposed : {false, true}) {
      const Eigen::VectorXd x = transposed ? lu.solveTransposed(b) : lu.solve(b);
      const Eigen::MatrixXd At = transposed ? Eigen::MatrixXd(A1.transpose()) : A1;
      EXPECT_LT(backwardError(At, x, b), 2.2e-16 * std::sqrt(double(n))) << "transposed " << transposed;
    }
    EXPECT_TRUE(lu.factorsAreStale());  // served by the kept factors, not a new LU
    EXPECT_EQ(lu.staleRefactorizations(), 0);
    EXPECT_GT(lu.krylovIterations(), 2);   // the kept factors alone are not the answer
    EXPECT_LE(lu.krylovIterations(), 2 * DenseLu::maxKrylovIterations);
  }
}

// Kept factors of a matrix unlike the new one: GMRES does not converge within its
// limit, the new matrix is factored and the answer is its LU's. Where there are no
// factors of the size, nothing is taken.
TEST(DenseLu, KeptFactorsOfAnUnrelatedMatrixEndInItsOwnLu) {
  const int n = 300;
  const Eigen::MatrixXd A0 = withCondition(n, 1e3, 15), A1 = withCondition(n, 1e3, 16);
  const Eigen::VectorXd b = Eigen::VectorXd::Random(n);
  DenseLu lu(A0);
  Eigen::MatrixXd taken = A1;
  ASSERT_TRUE(lu.reuseFactorsFor(taken));
  const Eigen::VectorXd x = lu.solve(b);
  EXPECT_EQ(lu.staleRefactorizations(), 1);
  EXPECT_EQ(lu.krylovIterations(), DenseLu::maxKrylovIterations);
  EXPECT_FALSE(lu.factorsAreStale());
  EXPECT_LT(backwardError(A1, x, b), 2.2e-16 * std::sqrt(double(n)));

  DenseLu none;
  Eigen::MatrixXd other = A1;
  EXPECT_FALSE(none.reuseFactorsFor(other));
  EXPECT_EQ(other, A1);  // not taken
  Eigen::MatrixXd smaller = A1.topLeftCorner(10, 10);
  EXPECT_FALSE(lu.reuseFactorsFor(smaller));
}

// Kept factors that needed more iterations than they are worth are not kept again.
TEST(DenseLu, KeptFactorsThatCostTooManyIterationsAreNotKeptAgain) {
  const int n = 300;
  const Eigen::MatrixXd A0 = withCondition(n, 1e3, 17);
  std::srand(18);
  const Eigen::MatrixXd A1 = A0 + 3e-5 * Eigen::MatrixXd::Random(n, n);  // ||A0^-1 dA|| ~ 1
  const Eigen::VectorXd b = Eigen::VectorXd::Random(n);
  DenseLu lu(A0);
  Eigen::MatrixXd taken = A1;
  ASSERT_TRUE(lu.reuseFactorsFor(taken));
  lu.solve(b);
  ASSERT_EQ(lu.staleRefactorizations(), 0);
  ASSERT_GT(lu.krylovIterations(), DenseLu::staleIterationBudget(n));
  Eigen::MatrixXd next = A1;
  EXPECT_FALSE(lu.reuseFactorsFor(next));
}
