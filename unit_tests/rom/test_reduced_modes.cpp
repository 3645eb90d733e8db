// rom::reducedModes and the rigid-body checks on small dense chains: the uniform
// fixed-free chain's eigenvalues and shapes in closed form, mass normalisation,
// and a free-free chain's rigid-body mode refused where a zero-frequency
// compliance would need K^{-1}.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "DenseSystems.hpp"
#include "cyclone/core/Error.hpp"
#include "cyclone/rom/GuyanModel.hpp"
#include "cyclone/rom/HybridFrfModel.hpp"
#include "cyclone/rom/ReducedModes.hpp"

using namespace cyclone;
using namespace rom_test;

namespace {

// n equal masses m on n equal springs k, mass 0 on the ground:
//   w_j^2 = (4 k / m) sin^2(theta_j / 2),  u_j(i) = sin((i + 1) theta_j),  theta_j = (2 j + 1) pi / (2 n + 1).
double uniformChainEigenvalue(int n, double k, double m, int j) {
  const double theta = (2 * j + 1) * M_PI / (2 * n + 1);
  return 4 * k / m * std::pow(std::sin(theta / 2), 2);
}

Eigen::VectorXd uniformChainShape(int n, int j) {
  const double theta = (2 * j + 1) * M_PI / (2 * n + 1);
  Eigen::VectorXd u(n);
  for (int i = 0; i < n; ++i) u(i) = std::sin((i + 1) * theta);
  return u;
}

}  // namespace

TEST(RomReducedModes, UniformChainClosedForm) {
  const int n = 16, retained = 4;
  const double k = 2.5e4, m = 0.8;
  const DenseSystem s = uniformChain(n, k, m);
  const auto modes = rom::reducedModes(s.K, s.M, retained, 1);
  ASSERT_EQ(modes.numModes(), n);
  ASSERT_EQ(modes.shapes.rows(), retained);
  double worstValue = 0, worstShape = 0;
  for (int j = 0; j < n; ++j) {
    worstValue = std::max(worstValue, std::abs(modes.eigenvalues[j] / uniformChainEigenvalue(n, k, m, j) - 1));
    // Mass-normalised closed-form shape (u^T M u = m |u|^2), its leading rows; the sign is free.
    const Eigen::VectorXd u = uniformChainShape(n, j) / std::sqrt(m * uniformChainShape(n, j).squaredNorm());
    const Eigen::VectorXd got = modes.shapes.col(j);
    const double sign = got.dot(u.head(retained)) < 0 ? -1.0 : 1.0;
    worstShape = std::max(worstShape, (sign * got - u.head(retained)).norm() / u.head(retained).norm());
  }
  std::printf("uniform chain: eigenvalues %.2e, shapes %.2e (relative, worst over %d modes)\n", worstValue, worstShape,
              n);
  EXPECT_LT(worstValue, 1e-12);
  EXPECT_LT(worstShape, 1e-10);
}

// The shapes are the rows of mass-normalised eigenvectors: with every DOF kept,
// Phi^T M Phi = I and K Phi = M Phi Lambda for a general (fully coupled) K.
TEST(RomReducedModes, MassNormalisedEigenpairs) {
  const DenseSystem s = randomSpd(9, 11);
  const auto modes = rom::reducedModes(s.K, s.M, s.size(), 2);
  EXPECT_EQ(modes.copies, 2);
  const Eigen::MatrixXd& phi = modes.shapes;
  const Eigen::VectorXd lambda = Eigen::Map<const Eigen::VectorXd>(modes.eigenvalues.data(), modes.numModes());
  const double orthonormal = (phi.transpose() * s.M * phi - Eigen::MatrixXd::Identity(9, 9)).norm();
  const double residual = relativeError(s.K * phi, s.M * phi * lambda.asDiagonal());
  std::printf("random SPD: |Phi^T M Phi - I| %.2e, eigen-residual %.2e\n", orthonormal, residual);
  EXPECT_LT(orthonormal, 1e-12);
  EXPECT_LT(residual, 1e-12);
  for (int j = 1; j < modes.numModes(); ++j) EXPECT_LE(modes.eigenvalues[j - 1], modes.eigenvalues[j]);
}

// A massless DOF (singular M) has no mass-normalised modes.
TEST(RomReducedModes, SingularMassIsRefused) {
  DenseSystem s = gradedChain(5);
  s.M(2, 2) = 0.0;
  EXPECT_THROW(rom::reducedModes(s.K, s.M, 2, 1), InputError);
}

// An indefinite M is refused (Eigen's generalised solver alone reported Success with
// meaningless eigenvalues for it; a singular M failed only because its factor filled
// with NaN).
TEST(RomReducedModes, IndefiniteMassIsRefused) {
  DenseSystem s = gradedChain(5);
  s.M(2, 2) = -1.0;
  EXPECT_THROW(rom::reducedModes(s.K, s.M, 2, 1), InputError);
}

// A free-free chain has one rigid-body mode (eigenvalue ~1e-16 of the largest): it
// is counted, and the zero-frequency compliance (K^{-1}, which does not exist) is refused.
TEST(RomReducedModes, FreeChainRigidBodyMode) {
  const DenseSystem held = gradedChain(8), free = gradedChain(8, false);
  const auto freeModes = rom::reducedModes(free.K, free.M, 3, 1);
  const auto heldModes = rom::reducedModes(held.K, held.M, 3, 1);
  EXPECT_EQ(freeModes.numRigidBodyModes(), 1);
  EXPECT_EQ(heldModes.numRigidBodyModes(), 0);
  EXPECT_THROW(rom::requireNonsingularStiffness(free.K, "test"), InputError);
  EXPECT_NO_THROW(rom::requireNonsingularStiffness(held.K, "test"));
  EXPECT_THROW(rom::HybridFrfModel::modalTruncation(freeModes, 0.01).zeroFrequencyCompliance(), InputError);
  // Guyan onto DOFs of the free chain: K_g inherits the rigid motion (det K = det K_ii det K_g).
  const rom::GuyanModel guyan(boundaryReduction(reordered(free, {2, 7}), 2), 0.01);
  EXPECT_THROW(guyan.zeroFrequencyCompliance(), InputError);
}

// first(distinct) keeps the lowest frequencies with both real-form copies of a pair.
TEST(RomReducedModes, FirstKeepsPairsTogether) {
  const DenseSystem s = randomSpd(6, 3);
  const auto modes = rom::reducedModes(s.K, s.M, 4, 2);
  const auto kept = modes.first(2);
  ASSERT_EQ(kept.numModes(), 4);
  EXPECT_EQ(kept.copies, 2);
  EXPECT_EQ(kept.shapes, modes.shapes.leftCols(4));
  for (int j = 0; j < 4; ++j) EXPECT_EQ(kept.eigenvalues[j], modes.eigenvalues[j]);
  EXPECT_THROW(modes.first(0), InputError);
  EXPECT_THROW(modes.first(4), InputError);  // 4 pairs = 8 modes, only 6 computed
}
