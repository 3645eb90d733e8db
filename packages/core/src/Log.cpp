#include "cyclone/core/Log.hpp"
#include "cyclone/core/LogSink.hpp"

#include <chrono>
#include <cstdio>
#include <utility>

namespace cyclone::log {
namespace {
bool g_quiet = false;
int g_rank = 0;
Sink g_sink;
const auto g_start = std::chrono::steady_clock::now();
double elapsed() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - g_start).count();
}
}  // namespace

void setQuiet(bool quiet) { g_quiet = quiet; }
void setRank(int rank) { g_rank = rank; }
void setSink(Sink sink) { g_sink = std::move(sink); }

void info(const std::string& message) {
  if (g_quiet || g_rank != 0) return;
  if (g_sink) return g_sink(Level::Info, message);
  std::printf("[cyclone %7.1fs] %s\n", elapsed(), message.c_str());
  std::fflush(stdout);
}

void warn(const std::string& message) {
  if (g_rank != 0) return;
  if (g_sink) return g_sink(Level::Warning, message);
  std::fprintf(stderr, "[cyclone %7.1fs] warning: %s\n", elapsed(), message.c_str());
}

}  // namespace cyclone::log
