#pragma once
// The program's stack limit (RLIMIT_STACK, `ulimit -s`) made enough for the element
// kernels before anything runs: their fixed-size matrices (60 x 60 doubles each) overran a
// stack of 256 kB or 512 kB, and the demo's disc died by SIGSEGV in the assembly with its
// manifest left "running" (a fifth probe).

namespace cyclone::scenes {

/// The stack the kernels are known to need, and the one the program asks for.
constexpr unsigned long kStackNeededBytes = 2ul << 20, kStackWantedBytes = 8ul << 20;

/// Called first in main, before MPI starts: a soft limit below kStackWantedBytes is raised
/// towards it (up to the hard limit) and the program started again under it (glibc sizes
/// the threads' stacks from the limit it starts with); returns only where nothing needed
/// raising or the exec failed. Returns false, having said why on stderr, where the hard
/// limit stays below kStackNeededBytes.
bool ensureStack(char** argv);

}  // namespace cyclone::scenes
