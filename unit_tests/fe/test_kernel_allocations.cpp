// The element kernels allocate nothing: every element-sized array keeps its storage
// inside the object. Counted, not assumed: this test program puts its own malloc,
// calloc and realloc in front of glibc's (which they call), so every heap allocation
// of the process, Eigen's and operator new's included, passes a counter.
#include <gtest/gtest.h>

#include <atomic>
#include <cstddef>
#include <random>

#include "ElementTestSupport.hpp"
#include "cyclone/fe/ElementKernels.hpp"

extern "C" {
void* __libc_malloc(std::size_t);
void* __libc_calloc(std::size_t, std::size_t);
void* __libc_realloc(void*, std::size_t);
void __libc_free(void*);
}

namespace {
std::atomic<long> allocations{0};
}

extern "C" {
void* malloc(std::size_t n) {
  allocations.fetch_add(1, std::memory_order_relaxed);
  return __libc_malloc(n);
}
void* calloc(std::size_t count, std::size_t size) {
  allocations.fetch_add(1, std::memory_order_relaxed);
  return __libc_calloc(count, size);
}
void* realloc(void* p, std::size_t n) {
  allocations.fetch_add(1, std::memory_order_relaxed);
  return __libc_realloc(p, n);
}
void free(void* p) { __libc_free(p); }
}

using namespace cyclone;
using namespace cyclone::fe;

namespace {

// Keeps the compiler from removing a computation whose result is not otherwise used.
template <class T>
void keep(const T& value) {
  asm volatile("" : : "r"(&value) : "memory");
}

// Every kernel once on one element.
void everyKernel(ElementType type, const ElementCoords& X, const IsotropicElastic& mat, const ElementVector& u,
                 const PointStresses& stress, const RotationAxis& axis) {
  ElementMatrix K, M;
  for (const auto kind :
       {ElementPrestress::Kind::None, ElementPrestress::Kind::Linear, ElementPrestress::Kind::Nonlinear}) {
    ElementPrestress p;
    p.kind = kind, p.omega = 1000.0, p.axis = axis, p.stress = &stress, p.displacement = &u;
    elementModalMatrices(type, X, mat, p, K, &M);
    keep(K), keep(M);
  }
  keep(elementStiffness(type, X, mat));
  keep(elementMass(type, X, mat.rho));
  keep(elementGeometricStiffness(type, X, stress));
  keep(elementSpinSoftening(type, X, mat.rho, 1000.0, axis));
  keep(elementTotalLagrangian(type, X, mat, u, true));
  keep(elementStresses(type, X, mat, u));
  keep(elementCentrifugalLoad(type, X, mat.rho, 1000.0, axis));
  keep(elementBodyLoad(type, X, Eigen::Vector3d(0, 0, -9.81)));
  keep(elementVolume(type, X));
}

}  // namespace

TEST(KernelAllocations, NoneInAnyElementKernel) {
  std::mt19937 rng(5);
  IsotropicElastic mat;
  RotationAxis axis;
  for (const ElementType type : test::kAllTypes) {
    const ElementCoords X = test::distortedElement(type, rng);
    ElementVector u = ElementVector::Zero(3 * test::nodeCount(type));
    u(1) = 0.01;
    const PointStresses stress = elementStresses(type, X, mat, u);
    everyKernel(type, X, mat, u, stress, axis);  // the rules' tables are built at the first call
    const long before = allocations.load();
    for (int repeat = 0; repeat < 10; ++repeat) everyKernel(type, X, mat, u, stress, axis);
    const long during = allocations.load() - before;
    EXPECT_EQ(during, 0) << test::nameOf(type) << ": " << during << " heap allocations in 10 passes";
  }
  // The counter sees what Eigen allocates (so the check above can fail).
  const long before = allocations.load();
  {
    Eigen::MatrixXd A = Eigen::MatrixXd::Identity(60, 60);
    keep(A);
  }
  EXPECT_GE(allocations.load() - before, 1);
}
