// turf-replay's terminal commands: the lines it understands, the named refusals of the rest, and lines read from a
// pipe on a thread of their own.
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <condition_variable>
#include <mutex>
#include <string>
#include <variant>
#include <vector>

#include "participants/replay/line_reader.h"
#include "participants/replay/replay_keys.h"

namespace turf {
namespace {

using namespace std::chrono_literals;

ReplayCommand Parsed(const std::string& line) {
  auto result = ParseReplayLine(line);
  const auto* refusal = std::get_if<ReplayRefusal>(&result);
  EXPECT_EQ(refusal, nullptr) << line << ": " << (refusal ? refusal->reason : "");
  return refusal ? ReplayCommand{} : std::get<ReplayCommand>(result);
}

idl::ControlError Refused(const std::string& line) {
  auto result = ParseReplayLine(line);
  const auto* refusal = std::get_if<ReplayRefusal>(&result);
  EXPECT_NE(refusal, nullptr) << line;
  return refusal ? refusal->code : idl::CONTROL_OK;
}

TEST(ReplayKeys, PauseResumeSeekAndSpeed) {
  EXPECT_EQ(Parsed("pause").kind, ReplayCommand::Kind::kPause);
  EXPECT_EQ(Parsed(" p \r").kind, ReplayCommand::Kind::kPause);
  EXPECT_EQ(Parsed("resume").kind, ReplayCommand::Kind::kResume);
  EXPECT_EQ(Parsed("play").kind, ReplayCommand::Kind::kResume);
  const ReplayCommand seek = Parsed("seek 12.5");
  EXPECT_EQ(seek.kind, ReplayCommand::Kind::kSeek);
  EXPECT_EQ(seek.seek_time_ns, 12'500'000'000);
  EXPECT_EQ(seek.request.op(), idl::OP_SEEK);
  EXPECT_EQ(Parsed("s\t0").seek_time_ns, 0);
  EXPECT_EQ(Parsed("speed 4").speed, 4.0);
  EXPECT_EQ(Parsed("speed max").speed, 0.0);
}

TEST(ReplayKeys, RefusesAnythingElseWithItsReason) {
  for (const char* line : {"", "   "}) EXPECT_EQ(Refused(line), idl::CONTROL_EMPTY) << "'" << line << "'";
  for (const char* line : {"jump 3", "pause now", "seek"}) EXPECT_EQ(Refused(line), idl::CONTROL_PARSE) << line;
  for (const char* line : {"seek nan", "seek inf", "seek 3s"})
    EXPECT_EQ(Refused(line), idl::CONTROL_BAD_ARGUMENTS) << line;
  for (const char* line : {"seek -1", "seek 1e10", "speed 0", "speed 1e7", "speed 1e-300"})
    EXPECT_EQ(Refused(line), idl::CONTROL_OUT_OF_RANGE) << line;
  EXPECT_EQ(Refused(std::string(kMaxReplayLine + 1, 'p')), idl::CONTROL_TOO_LARGE);
}

TEST(LineReader, HandsOverEachLineAndCutsAnOverlongOne) {
  int fds[2];
  ASSERT_EQ(::pipe(fds), 0);
  std::mutex mutex;
  std::condition_variable cv;
  std::vector<std::string> lines;
  {
    LineReader reader(fds[0], 8, [&](std::string_view line) {
      std::lock_guard<std::mutex> lock(mutex);
      lines.emplace_back(line);
      cv.notify_all();
    });
    const std::string input = "pause\nseek 2.5\n" + std::string(100, 'x') + "\nend\n";
    ASSERT_EQ(::write(fds[1], input.data(), input.size()), static_cast<ssize_t>(input.size()));
    std::unique_lock<std::mutex> lock(mutex);
    ASSERT_TRUE(cv.wait_for(lock, 10s, [&] { return lines.size() == 4; })) << lines.size();
  }
  EXPECT_EQ(lines[0], "pause");
  EXPECT_EQ(lines[1], "seek 2.5");
  EXPECT_EQ(lines[2], std::string(9, 'x'));  // cut to max + 1, so it is refused as too long
  EXPECT_EQ(lines[3], "end");
  ::close(fds[0]);
  ::close(fds[1]);
}

}  // namespace
}  // namespace turf
