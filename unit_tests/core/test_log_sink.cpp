// The log's sink (LogSink.hpp): a program embedding the library takes every line, with
// its level, in place of stdout and stderr; quiet still silences the info lines.
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "cyclone/core/Log.hpp"
#include "cyclone/core/LogSink.hpp"

using namespace cyclone;

TEST(LogSink, TakesEachLineWithItsLevel) {
  std::vector<std::pair<log::Level, std::string>> lines;
  log::setSink([&](log::Level level, const std::string& message) { lines.emplace_back(level, message); });
  log::info("tracing");
  log::warn("the trace stopped");
  log::setQuiet(true);
  log::info("not said");
  log::warn("said even when quiet");
  log::setQuiet(false);
  log::setSink({});
  log::info("on stdout again, not in the sink");
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0].first, log::Level::Info);
  EXPECT_EQ(lines[0].second, "tracing");
  EXPECT_EQ(lines[1].first, log::Level::Warning);
  EXPECT_EQ(lines[1].second, "the trace stopped");
  EXPECT_EQ(lines[2].second, "said even when quiet");
}
