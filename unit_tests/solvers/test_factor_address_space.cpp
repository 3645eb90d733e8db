// solvers::checkFactorAddressSpace under a soft address-space limit (RLIMIT_AS, what
// `ulimit -v` sets) lowered in this process: a factor that does not fit in the room the
// limit leaves is refused with the limit and the room named, one that fits passes, and
// without a limit nothing is checked. (Short of room for its work buffer OpenBLAS waits
// forever instead of failing: the demo's disc under `ulimit -v 600000` hung.)
#include <gtest/gtest.h>

#include <sys/resource.h>
#include <unistd.h>

#include <fstream>
#include <string>

#include "cyclone/core/AddressSpace.hpp"
#include "cyclone/core/Error.hpp"
#include "cyclone/solvers/SparseCholesky.hpp"

using namespace cyclone;

TEST(FactorAddressSpace, AFactorBeyondTheRoomALimitLeavesIsRefused) {
  rlimit saved{};
  ASSERT_EQ(getrlimit(RLIMIT_AS, &saved), 0);
  if (saved.rlim_cur == RLIM_INFINITY) {
    EXPECT_EQ(addressSpaceLeftBytes(), addressSpaceLimitBytes());
    EXPECT_NO_THROW(solvers::checkFactorAddressSpace(1000, 1e15, 8, true));  // no limit, no check
  }
  double pages = 0;
  std::ifstream("/proc/self/statm") >> pages;
  const double mapped = pages * double(sysconf(_SC_PAGESIZE));
  ASSERT_GT(mapped, 0);
  rlimit tight = saved;
  tight.rlim_cur = rlim_t(mapped) + (rlim_t(64) << 20);  // 64 MB of room
  if (saved.rlim_max != RLIM_INFINITY && tight.rlim_cur > saved.rlim_max) GTEST_SKIP() << "hard limit too low";
  ASSERT_EQ(setrlimit(RLIMIT_AS, &tight), 0);
  const double left = addressSpaceLeftBytes();
  std::string refused;
  try {
    solvers::checkFactorAddressSpace(5000, 1e8, 8, false);  // 1.2 GB
  } catch (const SolverError& e) {
    refused = e.what();
  }
  bool fits = true;
  try {
    solvers::checkFactorAddressSpace(5000, 1e5, 8, false);  // 1.2 MB
  } catch (const SolverError&) {
    fits = false;
  }
  ASSERT_EQ(setrlimit(RLIMIT_AS, &saved), 0);
  // 64 MB less what the process mapped or unmapped between the two reads (a stream's buffer: pages)
  EXPECT_NEAR(left, 64.0 * (1 << 20), 1 << 20);
  EXPECT_NE(refused.find("out of memory before the factorization of the matrix (5000 equations): it needs about 1144 MB"),
            std::string::npos)
      << refused;
  EXPECT_NE(refused.find("(ulimit -v, "), std::string::npos) << refused;
  EXPECT_TRUE(fits);
}
