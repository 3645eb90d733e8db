#include "cyclone/core/AddressSpace.hpp"

#include <dlfcn.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <fstream>
#include <limits>
#include <mutex>
#include <sstream>

#include "cyclone/core/Error.hpp"

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

namespace {
std::atomic<bool> bufferTaken{false};
std::mutex taking;
}  // namespace

void takeBlasWorkBuffer() {
  if (bufferTaken) return;
  std::lock_guard<std::mutex> lock(taking);
  if (bufferTaken) return;
  // Looked up at run time, as SingleThreadedBlas does: libblas/liblapack may be OpenBLAS's
  // or another library's (whose buffers, if any, are not this one).
  if (!dlsym(RTLD_DEFAULT, "openblas_get_num_threads")) return;
  using Potrf = void (*)(const char*, const int*, double*, const int*, int*);
  const auto potrf = reinterpret_cast<Potrf>(dlsym(RTLD_DEFAULT, "dpotrf_"));
  if (!potrf) return;
  const double left = addressSpaceLeftBytes();
  // The buffer and 16 MB for the allocator's own maps around it.
  const double need = kOpenBlasBufferBytes + 16.0 * (1 << 20);
  if (left < need) {
    const double mb = 1 << 20;
    std::ostringstream why;
    why << std::fixed;
    why.precision(0);
    why << "out of memory before any work: the process's address-space limit (ulimit -v, "
        << addressSpaceLimitBytes() / mb << " MB) leaves " << std::max(left, 0.0) / mb
        << " MB after start-up, less than the " << need / mb
        << " MB OpenBLAS's work buffer takes (OpenBLAS, short of room for it, waits forever instead of failing): "
           "raise the limit";
    throw SolverError(why.str());
  }
  const char lower = 'L';
  const int one = 1;
  double a = 1.0;
  int info = 0;
  potrf(&lower, &one, &a, &one, &info);  // the buffer is taken on the first call and kept
  bufferTaken = true;
}

bool blasWorkBufferTaken() { return bufferTaken; }

}  // namespace cyclone
