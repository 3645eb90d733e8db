#include <gtest/gtest.h>

#include "cyclone/post/Mac.hpp"

using namespace cyclone;

TEST(Mac, AutoMacOfOrthogonalModesIsIdentityAndScaleFree) {
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(5, 3);
  A(0, 0) = 2, A(1, 1) = -3, A(2, 2) = 0.5;
  A(3, 0) = 1;  // still orthogonal to the others
  const auto mac = post::macMatrix(A, A);
  EXPECT_LT((mac - Eigen::MatrixXd::Identity(3, 3)).norm(), 1e-15);
  // (a.b)^2 / (|a|^2 |b|^2) for two known vectors.
  Eigen::MatrixXd a(2, 1), b(2, 1);
  a << 1, 0;
  b << 1, 1;
  EXPECT_NEAR(post::macMatrix(a, b)(0, 0), 0.5, 1e-15);
}

TEST(Mac, SubspaceMacIgnoresRotationsWithinAPair) {
  Eigen::MatrixXd pair = Eigen::MatrixXd::Random(20, 2);
  const double t = 0.7;
  Eigen::Matrix2d R;
  R << std::cos(t), -std::sin(t), std::sin(t), std::cos(t);
  const Eigen::MatrixXd rotated = pair * R * 3.0;
  EXPECT_NEAR(post::subspaceMac(pair, rotated), 1.0, 1e-12);
  // The plain MAC of the members does see the rotation.
  EXPECT_LT(post::macMatrix(pair.col(0), rotated.col(0))(0, 0), 0.999);
  // An orthogonal pair scores 0.
  Eigen::MatrixXd e = Eigen::MatrixXd::Zero(4, 2), f = Eigen::MatrixXd::Zero(4, 2);
  e(0, 0) = e(1, 1) = 1;
  f(2, 0) = f(3, 1) = 1;
  EXPECT_NEAR(post::subspaceMac(e, f), 0.0, 1e-15);
}
