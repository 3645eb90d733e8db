#pragma once
// Progress and summary lines. Only MPI rank 0 prints (set once by the driver),
// so a 2-rank run does not show every line twice.
#include <string>

namespace cyclone::log {

void setQuiet(bool quiet);
void setRank(int rank);
/// "[cyclone] <message>" on stdout, flushed, with elapsed wall seconds since start.
void info(const std::string& message);
/// Same on stderr, tagged as a warning.
void warn(const std::string& message);

}  // namespace cyclone::log
