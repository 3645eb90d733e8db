// A projected receptance's dynamic stiffness by Woodbury's identity over its modal
// realization (a constant residual part plus modes, as a hybrid model's) against the
// plain inverse of its compliance, at frequencies below, between, at and above the
// modes, for several phases; and a realization whose residual part is singular (all
// modes kept), where the plain inverse is taken.
#include <gtest/gtest.h>

#include <chrono>
#include <complex>
#include <cstdio>
#include <memory>
#include <random>

#include "cyclone/hbm/ProjectedReceptance.hpp"
#include "ModalTestModel.hpp"

using namespace cyclone;
using namespace cyclone::hbm;

namespace {

using test_support::ModalTestModel;

double worstError(const ProjectedReceptance& q, double& seconds) {
  double worst = 0;
  seconds = 0;
  for (long p : {0L, 1L, 3L})
    for (double w : {0.3, 1.0, 4.5, 10.0, 17.3, 40.0, 55.0}) {
      const auto t = std::chrono::steady_clock::now();
      const Eigen::MatrixXcd Z = q.dynamicStiffness(w, p);
      seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
      const Eigen::MatrixXcd plain = q.compliance(w, p).inverse();
      worst = std::max(worst, (Z - plain).norm() / plain.norm());
    }
  return worst;
}

}  // namespace

TEST(ProjectedReceptance, WoodburyStiffnessIsThePlainInverse) {
  // 60 base DOFs seen through 24 coordinates (relative motions and kept DOFs), 12 modes.
  const int n = 60, q = 24, sectors = 8;
  std::mt19937 rng(3);
  std::normal_distribution<double> g;
  Eigen::MatrixXd T(q, n), Tn(q, n);
  for (int i = 0; i < T.size(); ++i) T.data()[i] = g(rng), Tn.data()[i] = 0.5 * g(rng);
  const ProjectedReceptance projected(std::make_shared<ModalTestModel>(n, 12, sectors, true), T, Tn);
  double seconds = 0;
  for (long p : {0L, 1L, 3L}) EXPECT_TRUE(projected.usesWoodbury(p)) << "phase " << p;
  const double error = worstError(projected, seconds);
  std::printf("Woodbury dynamic stiffness vs the plain inverse: %.1e (21 evaluations, %.4f s)\n", error, seconds);
  EXPECT_LT(error, 1e-10);
}

TEST(ProjectedReceptance, SingularResidualPartFallsBackToThePlainInverse) {
  // 10 DOFs, 10 modes and no residual part: R = 0, Woodbury does not apply.
  const int n = 10;
  const ProjectedReceptance projected(std::make_shared<ModalTestModel>(n, n, 1, false), Eigen::MatrixXd::Identity(n, n));
  EXPECT_FALSE(projected.usesWoodbury(0));
  double seconds = 0;
  EXPECT_LT(worstError(projected, seconds), 1e-12);
}
