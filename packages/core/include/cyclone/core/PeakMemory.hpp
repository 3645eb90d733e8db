#pragma once
// The process's peak resident memory so far (the kernel's high-water mark), for the
// per-stage memory lines of the log and the benchmarks.

namespace cyclone {

/// Peak resident set size of this process in MB (getrusage ru_maxrss).
double peakMemoryMb();

}  // namespace cyclone
