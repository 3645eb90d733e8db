#include "cyclone/core/Timer.hpp"

namespace cyclone {
Timer::Timer() : start_(std::chrono::steady_clock::now()) {}
void Timer::restart() { start_ = std::chrono::steady_clock::now(); }
double Timer::seconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}
}  // namespace cyclone
