#pragma once
#include <chrono>

namespace cyclone {

/// Wall-clock stopwatch for the error-against-run-time tables.
class Timer {
public:
  Timer();
  void restart();
  double seconds() const;

private:
  std::chrono::steady_clock::time_point start_;
};

}  // namespace cyclone
