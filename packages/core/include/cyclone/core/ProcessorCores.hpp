#pragma once
// How many processor cores this process may run on: what an automatic thread count
// starts from.

namespace cyclone {

/// The cores in this process's CPU affinity mask (taskset, a container's cpuset), at
/// least 1; std::thread::hardware_concurrency where there is no mask.
int usableProcessorCores();

}  // namespace cyclone
