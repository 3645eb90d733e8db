// The patch test: on a block of distorted elements, prescribing a linear displacement
// u = A x + c on the boundary nodes must reproduce it exactly at the interior nodes,
// with the constant stress D eps(A) at every integration point.
#include <gtest/gtest.h>

#include "ElementTestSupport.hpp"
#include "cyclone/mesh/ReferenceElement.hpp"

using namespace cyclone::fe;
using namespace cyclone::fe::test;

namespace {

class PatchTest : public ::testing::TestWithParam<ElementType> {};

TEST_P(PatchTest, LinearFieldIsReproducedWithExactConstantStress) {
  const auto t = GetParam();
  std::mt19937 rng(41);
  const PatchMesh mesh = distortedBlock(t, rng);
  IsotropicElastic mat;
  mat.E = 2.1e5;
  mat.nu = 0.3;

  Eigen::Matrix3d A;
  std::uniform_real_distribution<double> u(-1e-3, 1e-3);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) A(i, j) = u(rng);
  const Eigen::Vector3d c(0.1, -0.2, 0.05);

  const int nodes = static_cast<int>(mesh.nodes.size());
  Eigen::VectorXd exact(3 * nodes);
  std::vector<int> interior, boundary;  // DOF indices
  for (int n = 0; n < nodes; ++n) {
    exact.segment<3>(3 * n) = A * mesh.nodes[n] + c;
    for (int d = 0; d < 3; ++d) (mesh.onBoundary[n] ? boundary : interior).push_back(3 * n + d);
  }
  ASSERT_FALSE(interior.empty());

  const Eigen::MatrixXd K = assembleDense(mesh, [&](const ElementCoords& X) { return elementStiffness(t, X, mat); });
  const Eigen::VectorXd uB = exact(boundary);
  const Eigen::MatrixXd KII = K(interior, interior);
  const Eigen::VectorXd rhs = -K(interior, boundary) * uB;
  const Eigen::LLT<Eigen::MatrixXd> llt(KII);
  ASSERT_EQ(llt.info(), Eigen::Success);
  Eigen::VectorXd solution = exact;
  const Eigen::VectorXd interiorSolution = llt.solve(rhs);
  solution(interior) = interiorSolution;

  const double scale = exact.cwiseAbs().maxCoeff();
  EXPECT_LT((solution - exact).cwiseAbs().maxCoeff(), 1e-10 * scale)
      << interior.size() / 3 << " interior nodes of " << nodes;

  // Engineering strain of u = A x: eps_ij = (A_ij + A_ji) / 2, gamma_ij = A_ij + A_ji.
  Eigen::Matrix<double, 6, 1> strain;
  strain << A(0, 0), A(1, 1), A(2, 2), A(1, 2) + A(2, 1), A(0, 2) + A(2, 0), A(0, 1) + A(1, 0);
  const Eigen::Matrix<double, 6, 1> stress = lameElasticity(mat.E, mat.nu) * strain;
  const double stressScale = stress.cwiseAbs().maxCoeff();
  for (int e = 0; e < static_cast<int>(mesh.elements.size()); ++e) {
    const auto S = elementStresses(t, mesh.coords(e), mat, mesh.gather(e, solution));
    ASSERT_EQ(S.rows(), static_cast<Eigen::Index>(cyclone::mesh::stiffnessRule(t).points.size()));
    for (int q = 0; q < S.rows(); ++q)
      EXPECT_LT((S.row(q).transpose() - stress).cwiseAbs().maxCoeff(), 1e-10 * stressScale)
          << "element " << e << " point " << q;
  }
}

INSTANTIATE_TEST_SUITE_P(AllTypes, PatchTest, ::testing::ValuesIn(kAllTypes),
                         [](const auto& info) { return nameOf(info.param); });

}  // namespace
