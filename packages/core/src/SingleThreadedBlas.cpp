#include "cyclone/core/SingleThreadedBlas.hpp"

#include <dlfcn.h>

namespace cyclone {

namespace {
// Looked up at run time: the program links the reference BLAS interface (libblas.so.3),
// which Debian's alternatives may point at OpenBLAS or at another library.
using GetThreads = int (*)();
using SetThreads = void (*)(int);
GetThreads getThreads() { return reinterpret_cast<GetThreads>(dlsym(RTLD_DEFAULT, "openblas_get_num_threads")); }
SetThreads setThreads() { return reinterpret_cast<SetThreads>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads")); }
}  // namespace

SingleThreadedBlas::SingleThreadedBlas() {
  const auto get = getThreads();
  const auto set = setThreads();
  if (!get || !set) return;
  const int current = get();
  if (current <= 1) return;
  set(1);
  restore_ = current;
}

SingleThreadedBlas::~SingleThreadedBlas() {
  if (restore_ <= 0) return;
  if (const auto set = setThreads()) set(restore_);
}

}  // namespace cyclone
