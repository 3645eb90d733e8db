#pragma once
// The room a process's address-space limit (RLIMIT_AS, `ulimit -v`) leaves it. Under such
// a limit a failed allocation is not always an error one can catch: OpenBLAS waits
// forever for its work buffer (128 MB, first taken by its first LAPACK call), so the
// demo's disc under `ulimit -v 600000` hung after meshing. Callers check the room first.

namespace cyclone {

/// The soft limit in bytes; infinity without one.
double addressSpaceLimitBytes();

/// The limit less the address space mapped now (/proc/self/statm), in bytes (negative
/// where the process is past it); infinity without a limit.
double addressSpaceLeftBytes();

/// OpenBLAS's work buffer (Debian 12's libopenblas 0.3.21: 128 MiB and a page), which its
/// first LAPACK or level-3 call mallocs and keeps, retrying for ever where it cannot.
constexpr double kOpenBlasBufferBytes = 128.0 * (1 << 20) + 4096;

/// Where OpenBLAS is the process's BLAS: has it take its work buffer now, with a tiny
/// LAPACK call, after checking that the address-space limit leaves room for it (SolverError
/// naming the limit otherwise), so that no later call waits for it. The demo's disc under
/// `ulimit -v 600000` hung in its first CHOLMOD factorization, the Duffing scene in its
/// first dense LU. Once only; a no-op with another BLAS or without a limit's shortfall.
void takeBlasWorkBuffer();

/// Whether takeBlasWorkBuffer has had OpenBLAS take its buffer.
bool blasWorkBufferTaken();

}  // namespace cyclone
