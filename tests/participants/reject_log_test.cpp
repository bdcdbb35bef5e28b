// Refused input is logged with what the peer sent made printable (participants/common/process.h): a detail with a
// newline or a terminal escape cannot forge a log line or clear the operator's screen.
#include <gtest/gtest.h>
#include <spdlog/sinks/ringbuffer_sink.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <memory>
#include <string>

#include "participants/common/process.h"

namespace turf {
namespace {

TEST(Printable, ControlBytesAreWrittenAsEscapes) {
  EXPECT_EQ(Printable("Neck"), "Neck");
  EXPECT_EQ(Printable("a\nb\tc\x1b[2J\x7f"), "a\\x0ab\\x09c\\x1b[2J\\x7f");
  EXPECT_EQ(Printable(std::string("\0", 1)), "\\x00");
  EXPECT_EQ(Printable("Kopf \xc3\xa4"), "Kopf \xc3\xa4");  // UTF-8 as it is
}

TEST(RejectLog, TheDetailIsLoggedPrintable) {
  auto sink = std::make_shared<spdlog::sinks::ringbuffer_sink_mt>(8);
  spdlog::default_logger()->sinks().push_back(sink);
  RejectLog log("HLVS input");
  log.Reject("not_finite", "position of \"Neck\n[05:00:00.000] [turf-hlvs-bridge] [info] FORGED\x1b[2J\" is nan");
  auto& sinks = spdlog::default_logger()->sinks();
  sinks.erase(std::remove(sinks.begin(), sinks.end(), sink), sinks.end());
  const auto lines = sink->last_raw();
  ASSERT_EQ(lines.size(), 1u);
  const std::string text(lines[0].payload.begin(), lines[0].payload.end());
  EXPECT_EQ(text.find('\n'), std::string::npos) << text;
  EXPECT_EQ(text.find('\x1b'), std::string::npos) << text;
  EXPECT_NE(text.find("Neck\\x0a[05:00:00.000]"), std::string::npos) << text;
  EXPECT_EQ(log.Count("not_finite"), 1u);
}

}  // namespace
}  // namespace turf
