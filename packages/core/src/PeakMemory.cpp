#include "cyclone/core/PeakMemory.hpp"

#include <sys/resource.h>

namespace cyclone {

double peakMemoryMb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024.0;  // Linux reports kB
}

}  // namespace cyclone
