#include <gtest/gtest.h>
#include <sched.h>
#include <unistd.h>

#include "cyclone/core/PeakMemory.hpp"
#include "cyclone/core/ProcessorCores.hpp"

using namespace cyclone;

// The count follows the affinity mask (taskset, a container's cpuset), not the machine.
TEST(ProcessorCores, FollowTheAffinityMask) {
  cpu_set_t saved;
  ASSERT_EQ(sched_getaffinity(0, sizeof(saved), &saved), 0);
  EXPECT_EQ(usableProcessorCores(), CPU_COUNT(&saved));
  int first = 0;
  while (!CPU_ISSET(first, &saved)) ++first;
  cpu_set_t one;
  CPU_ZERO(&one);
  CPU_SET(first, &one);
  ASSERT_EQ(sched_setaffinity(0, sizeof(one), &one), 0);
  EXPECT_EQ(usableProcessorCores(), 1);
  ASSERT_EQ(sched_setaffinity(0, sizeof(saved), &saved), 0);
}

// MemAvailable is at most what the system has (MemTotal) and more than nothing.
TEST(PeakMemory, AvailableMemoryIsWithinTheMachine) {
  const double available = availableMemoryMb();
  EXPECT_GT(available, 0.0);
  long pages = sysconf(_SC_PHYS_PAGES), size = sysconf(_SC_PAGE_SIZE);
  EXPECT_LE(available, double(pages) * double(size) / (1024.0 * 1024.0));
}
