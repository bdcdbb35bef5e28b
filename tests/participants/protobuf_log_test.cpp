// libprotobuf's log lines through turf's rate-limited logger: a flood of datagrams with invalid UTF-8 in a string
// field (google.protobuf.Any.type_url of the simulation protocol's realism config) is counted, and printed a
// bounded number of times, not once per datagram.
#include "participants/common/protobuf_log.h"

#include <gtest/gtest.h>
#include <spdlog/sinks/ostream_sink.h>
#include <spdlog/spdlog.h>

#include <memory>
#include <sstream>
#include <string>

#include "codecs/proto/ssl_simulation.pb.h"
#include "tests/support/text.h"

namespace turf {
namespace {

TEST(ProtobufLog, InvalidUtf8FloodIsCountedAndRateLimited) {
  std::ostringstream captured;
  auto sink = std::make_shared<spdlog::sinks::ostream_sink_mt>(captured);
  auto previous = spdlog::default_logger();
  spdlog::set_default_logger(std::make_shared<spdlog::logger>("capture", sink));
  RouteProtobufLogs();

  wire::simulation::SimulatorCommand command;
  command.mutable_config()->mutable_realism_config()->add_custom()->set_type_url(std::string("bad \xff\xfe utf-8"));
  const std::string bytes = command.SerializeAsString();
  const uint64_t before = ProtobufLogLines();
  constexpr int kDatagrams = 200;
  for (int i = 0; i < kDatagrams; ++i) {
    wire::simulation::SimulatorCommand parsed;
    parsed.ParseFromString(bytes);  // fails or not: what matters here is what libprotobuf prints
  }
  spdlog::set_default_logger(previous);

  EXPECT_EQ(ProtobufLogLines() - before, static_cast<uint64_t>(kDatagrams))
      << "libprotobuf reported every bad datagram to turf's handler";
  const size_t printed = test::Occurrences(captured.str(), "libprotobuf");
  EXPECT_GE(printed, 1u) << "the first is told at once: " << captured.str();
  EXPECT_LE(printed, 2u) << "then at most a summary per 5 s: " << captured.str();
  EXPECT_NE(captured.str().find("invalid UTF-8"), std::string::npos) << captured.str();
}

}  // namespace
}  // namespace turf
