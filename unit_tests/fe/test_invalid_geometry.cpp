// Inverted and degenerate elements are reported as InvalidElementGeometry (with the
// offending det J), not turned into a meaningless matrix.
#include <gtest/gtest.h>

#include <functional>

#include "ElementTestSupport.hpp"

using namespace cyclone::fe;
using namespace cyclone::fe::test;

namespace {

// Runs every kernel on X and expects each to throw with det J satisfying `check`.
void expectEveryKernelRejects(ElementType t, const ElementCoords& X, const std::function<bool(double)>& check) {
  const IsotropicElastic mat;
  const Eigen::VectorXd ue = Eigen::VectorXd::Zero(3 * X.rows());
  const std::vector<std::pair<const char*, std::function<void()>>> kernels = {
      {"stiffness", [&] { elementStiffness(t, X, mat); }},
      {"mass", [&] { elementMass(t, X, 1.0); }},
      {"centrifugal", [&] { elementCentrifugalLoad(t, X, 1.0, 1.0, RotationAxis{}); }},
      {"body", [&] { elementBodyLoad(t, X, Eigen::Vector3d::UnitX()); }},
      {"volume", [&] { elementVolume(t, X); }},
      {"stresses", [&] { elementStresses(t, X, mat, ue); }},
  };
  for (const auto& [name, kernel] : kernels) {
    try {
      kernel();
      ADD_FAILURE() << nameOf(t) << " " << name << ": no exception";
    } catch (const InvalidElementGeometry& e) {
      EXPECT_TRUE(check(e.detJ)) << nameOf(t) << " " << name << ": det J = " << e.detJ;
      EXPECT_GE(e.point, 0);
      EXPECT_NE(std::string(e.what()).find("det J"), std::string::npos);
    }
  }
}

TEST(InvalidElementGeometry, TetWithTwoNodesSwappedIsInverted) {
  ElementCoords X(4, 3);
  X << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1;
  X.row(1).swap(X.row(2));
  expectEveryKernelRejects(ElementType::Tet4, X, [](double detJ) { return detJ == -1.0; });
}

TEST(InvalidElementGeometry, FlatTetIsDegenerate) {
  ElementCoords X(4, 3);
  X << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0.3, 0.3, 0;
  expectEveryKernelRejects(ElementType::Tet4, X, [](double detJ) { return detJ == 0.0; });
}

// Coordinates that are flat up to round-off give det J of order 1e-17, not a usable element.
TEST(InvalidElementGeometry, TetFlatToRoundOffIsDegenerate) {
  ElementCoords X(4, 3);
  X << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0.3, 0.3, 1e-17;
  expectEveryKernelRejects(ElementType::Tet4, X, [](double detJ) { return std::abs(detJ) < 1e-15; });
}

TEST(InvalidElementGeometry, MirroredElementsOfEveryTypeAreInverted) {
  std::mt19937 rng(61);
  for (auto t : kAllTypes) {
    ElementCoords X = distortedElement(t, rng);
    X.col(0) *= -1.0;
    expectEveryKernelRejects(t, X, [](double detJ) { return detJ < 0; });
  }
}

TEST(InvalidElementGeometry, ValidElementsAreAccepted) {
  std::mt19937 rng(62);
  for (auto t : kAllTypes) EXPECT_NO_THROW(elementStiffness(t, distortedElement(t, rng, 0.15), IsotropicElastic()));
}

TEST(ElementKernels, WrongNumberOfNodesIsAnError) {
  const ElementCoords X = ElementCoords::Zero(5, 3);
  EXPECT_THROW(elementStiffness(ElementType::Tet4, X, IsotropicElastic()), cyclone::Error);
  EXPECT_THROW(elementMass(ElementType::Hex8, X, 1.0), cyclone::Error);
}

}  // namespace
