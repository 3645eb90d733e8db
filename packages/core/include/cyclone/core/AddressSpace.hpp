#pragma once
// The room a process's address-space limit (RLIMIT_AS, `ulimit -v`) leaves it. Under such
// a limit a failed allocation is not always an error one can catch: OpenBLAS waits
// forever for its work buffer (128 MB, first taken in CHOLMOD's dense kernels), so the
// demo's disc under `ulimit -v 600000` hung after meshing. Callers check the room first.

namespace cyclone {

/// The soft limit in bytes; infinity without one.
double addressSpaceLimitBytes();

/// The limit less the address space mapped now (/proc/self/statm), in bytes (negative
/// where the process is past it); infinity without a limit.
double addressSpaceLeftBytes();

}  // namespace cyclone
