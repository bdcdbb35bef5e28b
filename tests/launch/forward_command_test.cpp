// `turf record` and `turf replay` run turf-record and turf-replay with the arguments as given.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <chrono>
#include <string>

#include "tests/support/process.h"

namespace turf::test {
namespace {

struct Ran {
  int status = -1;
  std::string output;
};

Ran Turf(const std::string& name, std::vector<std::string> args) {
  args.insert(args.begin(), Built("participants/launcher/turf"));
  Process p(name, args);
  const std::optional<int> status = p.Wait(std::chrono::seconds(20));
  EXPECT_TRUE(status.has_value());
  return {status && WIFEXITED(*status) ? WEXITSTATUS(*status) : -1, p.Log()};
}

TEST(TurfRecordReplay, SubcommandsRunTheParticipantsWithTheirFlags) {
  const Ran record = Turf("turf_record_help", {"record", "--help"});
  EXPECT_EQ(record.status, 0);
  EXPECT_NE(record.output.find("turf-record:"), std::string::npos) << record.output;
  EXPECT_NE(record.output.find("--compression"), std::string::npos) << record.output;
  const Ran replay = Turf("turf_replay_help", {"replay", "--help"});
  EXPECT_EQ(replay.status, 0);
  EXPECT_NE(replay.output.find("--speed"), std::string::npos) << replay.output;
  // A flag the program refuses: its exit status 2 and its reason.
  const Ran bad = Turf("turf_record_bad", {"record", "x.mcap", "--compression", "lzma"});
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.output.find("--compression"), std::string::npos) << bad.output;
  const Ran unknown = Turf("turf_record_unknown_topic", {"record", "x.mcap", "--topics", "world_state,nope"});
  EXPECT_EQ(unknown.status, 2);
  EXPECT_NE(unknown.output.find("no topic 'nope' (known: clock, world_state,"), std::string::npos) << unknown.output;
}

}  // namespace
}  // namespace turf::test
