#include "cyclone/core/ProcessorCores.hpp"

#include <sched.h>

#include <algorithm>
#include <thread>

namespace cyclone {

int usableProcessorCores() {
#if defined(__linux__)
  cpu_set_t mask;
  CPU_ZERO(&mask);
  if (sched_getaffinity(0, sizeof(mask), &mask) == 0) return std::max(1, CPU_COUNT(&mask));
#endif
  return std::max(1, int(std::thread::hardware_concurrency()));
}

}  // namespace cyclone
