#pragma once
// The process's resident memory, now and at its peak so far (the kernel's high-water
// mark), for the per-stage memory lines of the log and the benchmarks.

namespace cyclone {

/// Peak resident set size of this process in MB (getrusage ru_maxrss).
double peakMemoryMb();

/// Resident set size now in MB (/proc/self/status VmRSS; 0 where there is none).
double currentMemoryMb();

/// Hands memory the allocator keeps after a stage's large temporaries were freed back
/// to the system (glibc's malloc_trim), so that the next stage's high-water mark does
/// not count it. A no-op elsewhere.
void releaseFreedMemory();

}  // namespace cyclone
