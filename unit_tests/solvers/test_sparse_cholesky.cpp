// CHOLMOD's factor behind the cyclic eigen-solution against dense references: its
// halves, its refactorization with a kept symbolic analysis, a Hermitian complex matrix.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <complex>
#include <dlfcn.h>
#include <random>

#include "cyclone/core/Error.hpp"
#include "cyclone/core/SingleThreadedBlas.hpp"
#include "cyclone/solvers/SparseCholesky.hpp"

using namespace cyclone;

namespace {

// A random sparse Hermitian positive definite matrix (diagonally dominant), both triangles.
template <class Scalar>
Eigen::SparseMatrix<Scalar, Eigen::ColMajor, int> randomSpd(int n, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic> A = Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>::Zero(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < i; ++j)
      if ((i + 3 * j) % 5 == 0) {
        Scalar a;
        if constexpr (std::is_same_v<Scalar, double>) a = uniform(random);
        else a = Scalar(uniform(random), uniform(random));
        A(i, j) = a;
        A(j, i) = Eigen::numext::conj(a);
      }
  for (int i = 0; i < n; ++i) A(i, i) = 2.0 + A.row(i).cwiseAbs().sum();
  return A.sparseView();
}

template <class Scalar>
void checkHalvesAndRefactor() {
  using Dense = typename solvers::SparseCholesky<Scalar>::Dense;
  const int n = 40;
  const auto A = randomSpd<Scalar>(n, 7);
  const Dense dense = Dense(A);
  const Dense b = Dense::Random(n, 3);
  solvers::SparseCholesky<Scalar> factor(A);
  const Dense reference = dense.llt().solve(b);
  EXPECT_LT((factor.solve(b) - reference).norm(), 1e-12 * reference.norm());
  // solveUpper(solveLower(b)) = A^{-1} b, and the standard form L^{-1} P A P^T L^{-H} = I.
  EXPECT_LT((factor.solveUpper(factor.solveLower(b)) - reference).norm(), 1e-12 * reference.norm());
  const Dense identity = factor.solveLower(dense * factor.solveUpper(Dense::Identity(n, n)));
  EXPECT_LT((identity - Dense::Identity(n, n)).norm(), 1e-12 * n);

  // The same pattern, other values: refactored with the kept analysis.
  auto B = A;
  for (int k = 0; k < B.outerSize(); ++k)
    for (typename decltype(B)::InnerIterator it(B, k); it; ++it)
      if (it.row() == it.col()) it.valueRef() *= 3.0;
  ASSERT_TRUE(factor.refactor(B));
  const Dense referenceB = Dense(B).llt().solve(b);
  EXPECT_LT((factor.solve(b) - referenceB).norm(), 1e-12 * referenceB.norm());

  // Another pattern is refused and leaves the factor as it was.
  Dense other = Dense(B);
  other(n - 1, 0) += Scalar(0.01);  // an entry outside A's pattern
  other(0, n - 1) += Scalar(0.01);
  const Eigen::SparseMatrix<Scalar, Eigen::ColMajor, int> D = other.sparseView();
  EXPECT_FALSE(factor.refactor(D));
  EXPECT_LT((factor.solve(b) - referenceB).norm(), 1e-12 * referenceB.norm());

  // A matrix of the same pattern that is not positive definite is a SolverError.
  auto negative = B;
  negative *= Scalar(-1.0);
  EXPECT_THROW(factor.refactor(negative), SolverError);
}

}  // namespace

TEST(SparseCholesky, RealHalvesAndRefactorAgainstDense) { checkHalvesAndRefactor<double>(); }
TEST(SparseCholesky, ComplexHermitianHalvesAndRefactorAgainstDense) { checkHalvesAndRefactor<std::complex<double>>(); }

// OpenBLAS held at one thread while the library runs threads of its own, and given
// back its count afterwards (the solvers link the BLAS, which here is OpenBLAS).
TEST(SingleThreadedBlas, HoldsOpenBlasAtOneThreadAndRestoresIt) {
  using Get = int (*)();
  using Set = void (*)(int);
  const auto get = reinterpret_cast<Get>(dlsym(RTLD_DEFAULT, "openblas_get_num_threads"));
  const auto set = reinterpret_cast<Set>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
  if (!get || !set) GTEST_SKIP() << "the BLAS loaded is not OpenBLAS";
  const int before = get();
  set(2);
  {
    const SingleThreadedBlas single;
    EXPECT_EQ(get(), 1);
  }
  EXPECT_EQ(get(), 2);
  set(before);
}
