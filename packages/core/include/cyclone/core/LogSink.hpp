#pragma once
// Where progress lines go instead of stdout and stderr: a program that embeds the library
// (the Python module routes them to Python's logging) takes each line as it is written.
// A header of its own, so that the many files that write lines (Log.hpp) do not change.
#include <functional>
#include <string>

namespace cyclone::log {

enum class Level { Info, Warning };

/// Takes a line without the "[cyclone ...]" prefix; called on the thread that wrote it.
using Sink = std::function<void(Level level, const std::string& message)>;

/// Lines go to `sink` from now on (an empty one: back to stdout and stderr). Rank 0 only,
/// as printed lines; setQuiet silences info lines either way.
void setSink(Sink sink);

}  // namespace cyclone::log
