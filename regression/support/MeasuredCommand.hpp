#pragma once
// A shell command run as a forked child, measured: wall time, the kernel's high-water
// resident memory of the child (wait4's ru_maxrss: the largest single process of its
// tree), and the physical memory of the whole tree, sampled every 250 ms as the sum of
// the processes' proportional set sizes (PSS: a page shared by k processes counts 1/k in
// each, so a library mapped by two MPI ranks counts once). For a multi-process run
// (mpirun) the sum of each process's own peak overstates the memory it took (shared
// pages twice, peaks that did not coincide); the summed PSS is what the machine held.
#include <string>

namespace cyclone::regression {

struct MeasuredCommand {
  double seconds = 0;
  double peakResidentMb = 0;  ///< ru_maxrss of the child tree's largest process
  double peakTreePssMb = 0;   ///< the largest sampled sum of PSS over the tree
};

/// Runs `command` with /bin/sh; throws std::runtime_error naming it where it fails.
MeasuredCommand runMeasured(const std::string& command);

}  // namespace cyclone::regression
