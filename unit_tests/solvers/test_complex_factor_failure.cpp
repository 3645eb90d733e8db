// A complex factorization that fails says why in UMFPACK's terms: a zero pivot is a
// singular matrix, a lack of memory is not. (The seed-scale sector's 320k-equation
// complex LU, for the reduced model's check, stopped a 22-minute run with "the complex
// matrix ... is singular": UMFPACK had run out of memory.)
#include <Tpetra_CrsMatrix.hpp>
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <unistd.h>

#include <fstream>
#include <string>

#include "cyclone/core/AddressSpace.hpp"
#include "cyclone/core/Error.hpp"
#include "cyclone/core/SingleThreadedBlas.hpp"
#include "cyclone/solvers/DirectSolver.hpp"

using namespace cyclone;

namespace {

// The 7-point Laplacian of an m^3 grid plus `diagonal` on the diagonal; row `zero`
// (when >= 0) left out entirely.
Teuchos::RCP<linalg::Matrix> gridLaplacian(int m, double diagonal, long long zero) {
  const long long n = (long long)m * m * m;
  auto comm = Teuchos::rcp(new Teuchos::SerialComm<int>);
  auto map = Teuchos::rcp(new linalg::Map(n, 0, comm));
  auto A = Teuchos::rcp(new linalg::Matrix(map, 7));
  auto index = [m](int i, int j, int k) { return linalg::GlobalIndex(((long long)k * m + j) * m + i); };
  for (int k = 0; k < m; ++k)
    for (int j = 0; j < m; ++j)
      for (int i = 0; i < m; ++i) {
        const auto r = index(i, j, k);
        if (r == zero) continue;
        std::vector<linalg::GlobalIndex> cols{r};
        std::vector<double> values{6.0 + diagonal};
        const int d[3] = {i, j, k};
        for (int axis = 0; axis < 3; ++axis)
          for (int step : {-1, 1}) {
            int e[3] = {d[0], d[1], d[2]};
            e[axis] += step;
            if (e[axis] < 0 || e[axis] >= m) continue;
            const auto c = index(e[0], e[1], e[2]);
            if (c == zero) continue;
            cols.push_back(c), values.push_back(-1.0);
          }
        A->insertGlobalValues(r, Teuchos::ArrayView<const linalg::GlobalIndex>(cols),
                              Teuchos::ArrayView<const double>(values));
      }
  A->fillComplete();
  return A;
}

// The message of the factorization's failure ("" if it factors), "out of memory: "
// before it where the error is the typed OutOfMemoryError (what a check catches to go
// on without its solve).
std::string failureOf(const linalg::Matrix& A) {
  try {
    solvers::ComplexDirectSolver solver(A, {1.0, 0.01}, A, {0.0, 0.0});
  } catch (const OutOfMemoryError& e) {
    return std::string("OutOfMemoryError: ") + e.what();
  } catch (const SolverError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(ComplexFactorFailure, AZeroPivotIsSaidSingular) {
  const auto A = gridLaplacian(6, 1.0, 100);  // row and column 100 empty
  const std::string message = failureOf(*A);
  EXPECT_EQ(message.rfind("UMFPACK: the complex matrix (216 equations) is singular", 0), 0u) << message;
}

// Under an address-space limit that leaves the matrix built but its LU no room: out of
// memory, with UMFPACK's estimate of what it needed, not "singular".
TEST(ComplexFactorFailure, AFactorWithoutRoomIsSaidOutOfMemory) {
  const auto A = gridLaplacian(30, 1.0, -1);  // 27 000 equations: an LU of about a hundred MB
  // OpenBLAS short of room for its work buffers waits forever instead of failing: one
  // thread, its buffer taken first (as the program does at its start).
  const SingleThreadedBlas oneThread;
  takeBlasWorkBuffer();
  rlimit saved{};
  ASSERT_EQ(getrlimit(RLIMIT_AS, &saved), 0);
  double pages = 0;
  std::ifstream("/proc/self/statm") >> pages;
  const double mapped = pages * double(sysconf(_SC_PAGESIZE));
  rlimit tight = saved;
  tight.rlim_cur = rlim_t(mapped) + (rlim_t(64) << 20);  // 64 MB of room
  if (saved.rlim_max != RLIM_INFINITY && tight.rlim_cur > saved.rlim_max) GTEST_SKIP() << "hard limit too low";
  ASSERT_EQ(setrlimit(RLIMIT_AS, &tight), 0);
  std::string message;
  try {
    message = failureOf(*A);
  } catch (const std::bad_alloc&) {
    message = "std::bad_alloc outside UMFPACK";
  }
  ASSERT_EQ(setrlimit(RLIMIT_AS, &saved), 0);
  EXPECT_NE(message.find("OutOfMemoryError: UMFPACK: the complex matrix (27000 equations) could not be factored: out of memory"),
            std::string::npos)
      << message;
  EXPECT_NE(message.find("UMFPACK's estimate of its peak memory: "), std::string::npos) << message;
  EXPECT_EQ(message.find("singular"), std::string::npos) << message;
  // With room, the same matrix factors.
  EXPECT_EQ(failureOf(*A), "");
}
