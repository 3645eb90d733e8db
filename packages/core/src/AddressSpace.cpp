#include "cyclone/core/AddressSpace.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <fstream>
#include <limits>

namespace cyclone {

double addressSpaceLimitBytes() {
  rlimit limit{};
  if (getrlimit(RLIMIT_AS, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY)
    return std::numeric_limits<double>::infinity();
  return double(limit.rlim_cur);
}

double addressSpaceLeftBytes() {
  const double limit = addressSpaceLimitBytes();
  if (limit == std::numeric_limits<double>::infinity()) return limit;
  std::ifstream statm("/proc/self/statm");  // its first field: the pages mapped (VmSize)
  double pages = 0;
  if (!(statm >> pages)) return limit;
  return limit - pages * double(sysconf(_SC_PAGESIZE));
}

}  // namespace cyclone
