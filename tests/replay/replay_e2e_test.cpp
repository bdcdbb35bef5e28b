// turf-replay as a real process on a private domain: a recording (made here with the MCAP writer from serialized
// samples) is played back; every world state arrives in order and serializes to the recorded bytes, a recorded
// input (a blue command) is not played, and a message that is no CDR sample is refused and counted.
#include <fastdds/rtps/common/SerializedPayload.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <turf/idl/ClockPubSubTypes.h>
#include <turf/idl/SslRobotPubSubTypes.h>
#include <turf/idl/WorldStatePubSubTypes.h>
#include <unistd.h>

#include <chrono>
#include <condition_variable>
#include <mutex>
#include <string>
#include <vector>

#include "codecs/mcap/writer.h"
#include "dds/participant.h"
#include "participants/common/mcap_file.h"
#include "participants/recorder/idl_schema.h"
#include "tests/support/process.h"
#include "tests/test_domain.h"

namespace turf::test {
namespace {

using namespace std::chrono_literals;

template <class PubSub, class Sample>
std::string Cdr(const Sample& sample) {
  PubSub type;
  eprosima::fastrtps::rtps::SerializedPayload_t payload(type.getSerializedSizeProvider(const_cast<Sample*>(&sample))());
  EXPECT_TRUE(type.serialize(const_cast<Sample*>(&sample), &payload));
  return std::string(reinterpret_cast<const char*>(payload.data), payload.length);
}

// 100 world states (sim time 10 ms apart), blue commands between them, and one clock message that is no CDR.
std::vector<std::string> WriteRecording(const std::string& path) {
  McapFileSink sink(path);
  mcap::Writer w(&sink, {});
  const uint16_t ws_schema = w.AddSchema("turf::idl::WorldState", "omgidl", record::IdlSchema("WorldState"));
  const uint16_t cmd_schema = w.AddSchema("turf::idl::SslRobotCommand", "omgidl", record::IdlSchema("SslRobotCommand"));
  const uint16_t clock_schema = w.AddSchema("turf::idl::Clock", "omgidl", record::IdlSchema("Clock"));
  const uint16_t world = w.AddChannel(ws_schema, "old/world_state", "cdr");
  const uint16_t blue = w.AddChannel(cmd_schema, "old/ssl/command/blue", "cdr");
  const uint16_t clock = w.AddChannel(clock_schema, "old/clock", "cdr");
  std::vector<std::string> recorded;
  for (int i = 0; i < 100; ++i) {
    idl::WorldState s;
    s.sim_time_ns(10'000'000ll * (i + 1));
    s.frame(static_cast<uint64_t>(i + 1));
    s.robots().resize(2);
    s.robots()[1].position().x(0.01 * i);
    recorded.push_back(Cdr<idl::WorldStatePubSubType>(s));
    const uint64_t t = 1'700'000'000'000'000'000ull + 10'000'000ull * static_cast<uint64_t>(i);
    w.Write(world, static_cast<uint32_t>(i), t, static_cast<uint64_t>(s.sim_time_ns()), recorded.back());
    idl::SslRobotCommand c;
    c.id(static_cast<uint32_t>(i % 11));
    w.Write(blue, static_cast<uint32_t>(i), t + 1, 0, Cdr<idl::SslRobotCommandPubSubType>(c));
  }
  w.Write(clock, 0, 1'700'000'000'000'000'000ull, 0, std::string("\x00\x01\x00\x00\xff", 5));
  w.Close();
  sink.Flush();
  return recorded;
}

TEST(ReplayE2e, PlaysOutputsByteForByteAndNoInputs) {
  const int domain = TestDomain(43);
  const std::string prefix = "replay" + std::to_string(getpid());
  const std::string file = LogDir() + "/" + prefix + ".mcap";
  const std::vector<std::string> recorded = WriteRecording(file);

  dds::Participant participant({domain, "replay-test", prefix, TURF_SOURCE_DIR "/configs/qos/turf_qos.xml"});
  std::mutex mutex;
  std::condition_variable cv;
  std::vector<idl::WorldState> got;
  std::vector<idl::WorldState> batch;
  auto world = participant.MakeReader(dds::Topic::kWorldState, [&] { cv.notify_all(); });
  auto blue = participant.MakeReader(dds::Topic::kSslCommandBlue);

  Process replay(prefix, {Built("participants/replay/turf-replay"), file, "--speed", "1", "--wait-for-reader",
                          "--domain", std::to_string(domain), "--prefix", prefix});
  {
    std::unique_lock<std::mutex> lock(mutex);
    const bool all = cv.wait_for(lock, 30s, [&] {
      if (world->Take(&batch)) got.insert(got.end(), batch.begin(), batch.end());
      return got.size() >= recorded.size();
    });
    ASSERT_TRUE(all) << got.size() << " of " << recorded.size() << "\n" << replay.Log();
  }
  const std::optional<int> status = replay.Wait(30s);
  ASSERT_TRUE(status && WIFEXITED(*status) && WEXITSTATUS(*status) == 0) << replay.Log();
  ASSERT_EQ(got.size(), recorded.size());
  for (size_t i = 0; i < got.size(); ++i) {
    EXPECT_EQ(got[i].sim_time_ns(), 10'000'000ll * static_cast<int64_t>(i + 1));
    EXPECT_EQ(Cdr<idl::WorldStatePubSubType>(got[i]), recorded[i]) << i;
  }
  std::vector<idl::SslRobotCommand> commands;
  EXPECT_FALSE(blue->Take(&commands));  // inputs are never played
  EXPECT_EQ(blue->Matched(), 0);
  EXPECT_NE(replay.Log().find("replayed 100 messages (100 inputs or unknown channels skipped, 1 refused)"),
            std::string::npos)
      << replay.Log();
}

}  // namespace
}  // namespace turf::test
