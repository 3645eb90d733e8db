#pragma once
// The process's resident memory, now and at its peak so far (the kernel's high-water
// mark), for the per-stage memory lines of the log and the benchmarks.

namespace cyclone {

/// Peak resident set size of this process in MB (getrusage ru_maxrss).
double peakMemoryMb();

/// Resident set size now in MB (/proc/self/status VmRSS; 0 where there is none).
double currentMemoryMb();

/// Memory the system can give without swapping in MB (/proc/meminfo MemAvailable);
/// infinity where it is not known.
double availableMemoryMb();

/// For a program (process-wide, so not called by the library): blocks of 4 MB and more
/// are mapped on their own and handed back to the system when freed. glibc's default
/// raises that threshold to the size of each large block freed (up to 32 MB), after
/// which such blocks (Krylov bases, a factorization's work) come from the heap and stay
/// resident when freed; with two nodal diameters on threads that held about 30 MB more
/// at the peak (824 against 852 MiB, 1 % more time). A no-op elsewhere.
void returnLargeBlocksOnFree();

/// Hands memory the allocator keeps after a stage's large temporaries were freed back
/// to the system (glibc's malloc_trim), so that the next stage's high-water mark does
/// not count it. A no-op elsewhere.
void releaseFreedMemory();

}  // namespace cyclone
