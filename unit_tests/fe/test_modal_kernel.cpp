// The one-pass modal kernel (tangent and mass with J^-1 and w det J shared per point)
// against the single-term kernels it replaces in the sector's assembly, which are
// checked against closed forms in the other tests of this directory: every element
// type, distorted, with no prestress, a linear one (a stress field per point) and a
// nonlinear one (a displacement), with and without spin softening, both mass rules.
#include <gtest/gtest.h>

#include <random>

#include "ElementTestSupport.hpp"
#include "cyclone/core/Error.hpp"
#include "cyclone/fe/ElementKernels.hpp"
#include "cyclone/mesh/ReferenceElement.hpp"

using namespace cyclone;
using namespace cyclone::fe;

namespace {

double relativeDifference(const ElementMatrix& a, const ElementMatrix& b) { return (a - b).norm() / b.norm(); }

}  // namespace

TEST(ModalKernel, EqualsTheSingleTermKernelsSummed) {
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> uniform(-1, 1);
  IsotropicElastic mat;
  RotationAxis axis;
  axis.point = Eigen::Vector3d(0.1, -0.2, 0.0);
  axis.direction = Eigen::Vector3d(0.2, 0.1, 1.0);
  const double omega = 1047.0;
  for (const ElementType type : test::kAllTypes)
    for (const MassQuadrature quadrature : {MassQuadrature::Exact, MassQuadrature::StiffnessRule}) {
      const ElementCoords X = test::distortedElement(type, rng);
      const int n = test::nodeCount(type);
      ElementVector u(3 * n);
      for (int i = 0; i < 3 * n; ++i) u(i) = 0.01 * uniform(rng);
      const PointStresses stress = elementStresses(type, X, mat, u);
      for (const auto kind : {ElementPrestress::Kind::None, ElementPrestress::Kind::Linear,
                              ElementPrestress::Kind::Nonlinear})
        for (const double w : {0.0, omega}) {
          ElementPrestress p;
          p.kind = kind, p.omega = w, p.axis = axis, p.stress = &stress, p.displacement = &u;
          ElementMatrix K, M;
          elementModalMatrices(type, X, mat, p, K, &M, quadrature);
          ElementMatrix expected = kind == ElementPrestress::Kind::Nonlinear
                                       ? elementTotalLagrangian(type, X, mat, u, true).tangent
                                       : elementStiffness(type, X, mat);
          if (kind == ElementPrestress::Kind::Linear) expected += elementGeometricStiffness(type, X, stress);
          if (w != 0) expected -= elementSpinSoftening(type, X, mat.rho, w, axis, quadrature);
          const std::string what = test::nameOf(type) + " kind " + std::to_string(int(kind)) + " omega " +
                                   std::to_string(w) + " rule " + std::to_string(int(quadrature));
          EXPECT_LT(relativeDifference(K, expected), 1e-14) << what;
          EXPECT_EQ(K, K.transpose()) << what;
          EXPECT_LT(relativeDifference(M, elementMass(type, X, mat.rho, quadrature)), 1e-14) << what;
          // Without M asked for, the same K.
          ElementMatrix K2;
          elementModalMatrices(type, X, mat, p, K2, nullptr, quadrature);
          EXPECT_EQ(K2, K) << what;
        }
    }
}

TEST(ModalKernel, APrestressWithoutItsDataIsRefused) {
  std::mt19937 rng(3);
  const ElementCoords X = test::distortedElement(ElementType::Tet10, rng);
  ElementMatrix K;
  ElementPrestress linear;
  linear.kind = ElementPrestress::Kind::Linear;  // no stress
  EXPECT_THROW(elementModalMatrices(ElementType::Tet10, X, IsotropicElastic{}, linear, K, nullptr), Error);
  ElementPrestress nonlinear;
  nonlinear.kind = ElementPrestress::Kind::Nonlinear;
  const ElementVector shortDisplacement = ElementVector::Zero(6);
  nonlinear.displacement = &shortDisplacement;
  EXPECT_THROW(elementModalMatrices(ElementType::Tet10, X, IsotropicElastic{}, nonlinear, K, nullptr), Error);
}
