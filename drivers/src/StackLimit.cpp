#include "StackLimit.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>

namespace cyclone::scenes {

bool ensureStack(char** argv) {
  rlimit stack{};
  if (getrlimit(RLIMIT_STACK, &stack) != 0 || stack.rlim_cur == RLIM_INFINITY || stack.rlim_cur >= kStackWantedBytes)
    return true;
  const rlim_t wanted = stack.rlim_max == RLIM_INFINITY ? rlim_t(kStackWantedBytes)
                                                        : std::min(stack.rlim_max, rlim_t(kStackWantedBytes));
  if (wanted < kStackNeededBytes) {
    std::fprintf(stderr,
                 "cyclone: error: the stack limit (ulimit -s) is %lu kB and can be raised only to %lu kB: the element "
                 "computations need %lu kB (they overran 512 kB); raise the hard limit (ulimit -H -s)\n",
                 (unsigned long)(stack.rlim_cur >> 10), (unsigned long)(wanted >> 10), kStackNeededBytes >> 10);
    return false;
  }
  if (wanted <= stack.rlim_cur) return true;
  stack.rlim_cur = wanted;
  if (setrlimit(RLIMIT_STACK, &stack) != 0) return true;
  execv("/proc/self/exe", argv);  // the same program and arguments, under the raised limit
  return true;                    // exec failed: run on as it is
}

}  // namespace cyclone::scenes
