// `turf record` and `turf replay` run turf-record and turf-replay with the arguments as given.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <chrono>
#include <fstream>
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
  // A file that cannot be made, or read as MCAP: exit status 2 with the reason.
  const Ran nowhere = Turf("turf_record_nowhere", {"record", "/nonexistent-dir/x.mcap", "--domain", "97"});
  EXPECT_EQ(nowhere.status, 2);
  EXPECT_NE(nowhere.output.find("cannot write /nonexistent-dir/x.mcap"), std::string::npos) << nowhere.output;
  const std::string not_mcap = LogDir() + "/turf_replay_not_mcap.txt";
  { std::ofstream(not_mcap) << "hello"; }
  const Ran garbage = Turf("turf_replay_not_mcap", {"replay", not_mcap, "--domain", "97"});
  EXPECT_EQ(garbage.status, 2);
  EXPECT_NE(garbage.output.find("bad_magic at offset 0"), std::string::npos) << garbage.output;
}

}  // namespace
}  // namespace turf::test
