// turf-replay as a real process on a private domain: a recording (made here with the MCAP writer from serialized
// samples) is played back; every world state arrives in order and serializes to the recorded bytes, a recorded
// input (a blue command) is not played, and a message that is no CDR sample is refused and counted. Pause and
// seek over the control topic while it plays.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <turf/idl/ClockPubSubTypes.h>
#include <turf/idl/SslRobotPubSubTypes.h>
#include <turf/idl/WorldStatePubSubTypes.h>
#include <unistd.h>

#include <chrono>
#include <condition_variable>
#include <csignal>
#include <functional>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "codecs/mcap/writer.h"
#include "dds/control_client.h"
#include "dds/participant.h"
#include "participants/common/mcap_file.h"
#include "participants/recorder/idl_schema.h"
#include "tests/support/cdr.h"
#include "tests/support/process.h"
#include "tests/test_domain.h"

namespace turf::test {
namespace {

using namespace std::chrono_literals;

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

// Takes world states from `reader` until one has sim time `last_ns` or the deadline passes.
std::vector<idl::WorldState> Collect(dds::Reader<idl::WorldStatePubSubType>& reader, std::mutex& mutex,
                                     std::condition_variable& cv, int64_t last_ns) {
  std::vector<idl::WorldState> got, batch;
  std::unique_lock<std::mutex> lock(mutex);
  cv.wait_for(lock, 20s, [&] {
    if (reader.Take(&batch)) got.insert(got.end(), batch.begin(), batch.end());
    return !got.empty() && got.back().sim_time_ns() == last_ns;
  });
  return got;
}

// A recording of its own in the log folder, and a world-state reader on a private domain and prefix, for
// turf-replay to play that recording to.
struct Rig {
  Rig(int test_domain, const std::string& name)
      : domain(TestDomain(test_domain)),
        prefix(name + std::to_string(getpid())),
        file(LogDir() + "/" + prefix + ".mcap"),
        recorded(WriteRecording(file)),
        participant({domain, "replay-test", prefix, TURF_SOURCE_DIR "/configs/qos/turf_qos.xml"}),
        world(participant.MakeReader(dds::Topic::kWorldState, [this] { cv.notify_all(); })) {}

  // turf-replay of the file with `flags`, waiting for this reader.
  Process Replay(const std::vector<std::string>& flags) const {
    std::vector<std::string> argv = {Built("participants/replay/turf-replay"), file};
    argv.insert(argv.end(), flags.begin(), flags.end());
    argv.insert(argv.end(), {"--wait-for-reader", "--domain", std::to_string(domain), "--prefix", prefix});
    return Process(prefix, argv);
  }
  std::vector<idl::WorldState> CollectUntil(int64_t last_ns) { return Collect(*world, mutex, cv, last_ns); }

  const int domain;
  const std::string prefix, file;
  const std::vector<std::string> recorded;
  std::mutex mutex;
  std::condition_variable cv;
  dds::Participant participant;
  std::unique_ptr<dds::Reader<idl::WorldStatePubSubType>> world;
};

// Every sample received is the recorded one of its sim time, byte for byte, in order.
void ExpectRecordedInOrder(const std::vector<idl::WorldState>& got, const std::vector<std::string>& recorded) {
  int64_t previous = 0;
  for (const idl::WorldState& s : got) {
    const int64_t index = s.sim_time_ns() / 10'000'000 - 1;
    ASSERT_TRUE(index >= 0 && index < static_cast<int64_t>(recorded.size())) << s.sim_time_ns();
    EXPECT_GT(s.sim_time_ns(), previous);
    EXPECT_EQ(Cdr<idl::WorldStatePubSubType>(s), recorded[static_cast<size_t>(index)]) << index;
    previous = s.sim_time_ns();
  }
}

std::string Missing(const std::vector<idl::WorldState>& got, size_t first, size_t count) {
  std::vector<bool> seen(count, false);
  for (const idl::WorldState& s : got) {
    const size_t i = static_cast<size_t>(s.sim_time_ns() / 10'000'000 - 1);
    if (i >= first && i - first < count) seen[i - first] = true;
  }
  std::string out;
  for (size_t i = 0; i < count; ++i)
    if (!seen[i]) out += std::to_string(first + i) + " ";
  return out.empty() ? "none" : out;
}

TEST(ReplayE2e, PlaysOutputsByteForByteAndNoInputs) {
  Rig rig(43, "replay");
  auto blue = rig.participant.MakeReader(dds::Topic::kSslCommandBlue);

  Process replay = rig.Replay({"--speed", "1"});
  const std::vector<idl::WorldState> got = rig.CollectUntil(1'000'000'000);
  const std::optional<int> status = replay.Wait(30s);
  ASSERT_TRUE(status && WIFEXITED(*status) && WEXITSTATUS(*status) == 0) << replay.Log();
  EXPECT_NE(replay.Log().find("replayed 100 messages (100 inputs or unknown channels skipped, 1 refused, 0 before"),
            std::string::npos)
      << replay.Log();
  EXPECT_NE(replay.Log().find("onto DDS domain " + std::to_string(rig.domain) + ", prefix '" + rig.prefix + "'"),
            std::string::npos)
      << replay.Log();
  // DDS may drop a sample under load (KEEP_LAST 8, dds notes); what arrives is exactly what was recorded.
  EXPECT_GE(got.size(), 95u) << "missing: " << Missing(got, 0, 100);
  ASSERT_FALSE(got.empty());
  EXPECT_EQ(got.back().sim_time_ns(), 1'000'000'000);
  ExpectRecordedInOrder(got, rig.recorded);
  std::vector<idl::SslRobotCommand> commands;
  EXPECT_FALSE(blue->Take(&commands));  // inputs are never played
  EXPECT_EQ(blue->Matched(), 0);
}

TEST(ReplayE2e, StartSkipsTheRecordedTimeBeforeIt) {
  Rig rig(44, "replaystart");
  Process replay = rig.Replay({"--start", "0.5"});
  const std::vector<idl::WorldState> got = rig.CollectUntil(1'000'000'000);
  const std::optional<int> status = replay.Wait(30s);
  ASSERT_TRUE(status && WIFEXITED(*status) && WEXITSTATUS(*status) == 0) << replay.Log();
  // The recording's world states are 10 ms apart from the first message: 50 lie before 0.5 s (and the clock
  // message), 50 after.
  EXPECT_NE(replay.Log().find("replayed 50 messages"), std::string::npos) << replay.Log();
  EXPECT_NE(replay.Log().find("51 before --start"), std::string::npos) << replay.Log();
  ASSERT_FALSE(got.empty());
  EXPECT_GE(got.size(), 45u) << "missing: " << Missing(got, 50, 50);
  EXPECT_GE(got.front().sim_time_ns(), 510'000'000);  // none before the start
  EXPECT_EQ(got.back().sim_time_ns(), 1'000'000'000);
  ExpectRecordedInOrder(got, rig.recorded);
}

idl::SimControl Request(idl::ControlOp op, int64_t seek_ns = 0) {
  idl::SimControl r;
  r.op(op);
  r.seek_time_ns(seek_ns);
  return r;
}

// Splits arrival-ordered sim times (10 ms apart when played in order) into runs that each go forward without a
// jump (a gap of more than 5 samples: more than DDS drops at this pace).
std::vector<std::vector<int64_t>> Runs(const std::vector<int64_t>& times) {
  std::vector<std::vector<int64_t>> runs;
  for (const int64_t t : times) {
    if (runs.empty() || t <= runs.back().back() || t > runs.back().back() + 50'000'000) runs.emplace_back();
    runs.back().push_back(t);
  }
  return runs;
}

std::string Show(const std::vector<int64_t>& times) {
  std::string out;
  for (const int64_t t : times) out += std::to_string(t / 1'000'000) + " ";
  return out;
}

// At a tenth of the recorded pace: a pause stops the stream at the sim time its reply names; a seek back while
// paused plays again from 50 ms once resumed; a seek forward goes on at 900 ms; a seek past the end (while paused)
// is refused when the file ends. A replay refuses what would change the match. The sim times received form exactly
// those runs.
// Ctrl-C while --wait-for-reader waits (no reader on its prefix) is a clean stop, as at any other moment.
TEST(ReplayE2e, ACtrlCWhileWaitingForAReaderStopsCleanly) {
  Rig rig(43, "replaywait");
  Process replay(rig.prefix, {Built("participants/replay/turf-replay"), rig.file, "--no-stdin", "--wait-for-reader",
                              "--domain", std::to_string(rig.domain), "--prefix", rig.prefix + "alone"});
  const auto deadline = std::chrono::steady_clock::now() + 30s;
  while (replay.Log().find("waiting for a reader") == std::string::npos && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(20ms);  // polling the log
  ASSERT_NE(replay.Log().find("waiting for a reader"), std::string::npos) << replay.Log();
  replay.Signal(SIGINT);
  const std::optional<int> status = replay.Wait(30s);
  ASSERT_TRUE(status.has_value()) << replay.Log();
  EXPECT_TRUE(WIFEXITED(*status) && WEXITSTATUS(*status) == 0) << replay.Log();
  EXPECT_NE(replay.Log().find("stopped while waiting for a reader"), std::string::npos) << replay.Log();
  EXPECT_NE(replay.Log().find("stopped cleanly"), std::string::npos) << replay.Log();
}

TEST(ReplayE2e, PausesAndSeeksOverTheControlTopic) {
  constexpr int64_t kMs = 1'000'000;
  Rig rig(47, "replayseek");
  dds::ControlClient control(rig.participant, "replay-test");
  Process replay = rig.Replay({"--speed", "0.1"});
  std::vector<int64_t> seen;  // sim times in arrival order
  const auto wait_for = [&](const std::function<bool()>& done) {
    std::unique_lock<std::mutex> lock(rig.mutex);
    return rig.cv.wait_for(lock, 30s, [&] {
      std::vector<idl::WorldState> batch;
      if (rig.world->Take(&batch))
        for (const idl::WorldState& s : batch) seen.push_back(s.sim_time_ns());
      return done();
    });
  };
  const auto call = [&](const idl::SimControl& request) { return control.Call(request, 30s); };

  ASSERT_TRUE(wait_for([&] { return !seen.empty() && seen.back() >= 200 * kMs; })) << Show(seen) << replay.Log();
  const dds::ControlOutcome pause = call(Request(idl::OP_PAUSE));
  ASSERT_TRUE(pause.ok()) << pause.Describe() << replay.Log();
  const int64_t paused_at = pause.reply->sim_time_ns();
  const dds::ControlOutcome back = call(Request(idl::OP_SEEK, 50 * kMs));
  ASSERT_TRUE(back.ok()) << back.Describe() << replay.Log();
  EXPECT_EQ(back.reply->sim_time_ns(), 50 * kMs);
  const dds::ControlOutcome teleport = call(Request(idl::OP_TELEPORT_BALL));
  EXPECT_EQ(teleport.code(), idl::CONTROL_NOT_ALLOWED) << teleport.Describe();
  ASSERT_TRUE(call(Request(idl::OP_RESUME)).ok());
  ASSERT_TRUE(wait_for([&] { return Runs(seen).size() >= 2 && seen.back() >= 80 * kMs; })) << Show(seen);
  const dds::ControlOutcome forward = call(Request(idl::OP_SEEK, 900 * kMs));
  ASSERT_TRUE(forward.ok()) << forward.Describe() << replay.Log();
  EXPECT_EQ(forward.reply->sim_time_ns(), 900 * kMs);
  ASSERT_TRUE(wait_for([&] { return seen.back() >= 920 * kMs; })) << Show(seen);
  ASSERT_TRUE(call(Request(idl::OP_PAUSE)).ok());  // so the file cannot end before the seek arrives
  const dds::ControlOutcome past_end = call(Request(idl::OP_SEEK, 5000 * kMs));
  EXPECT_EQ(past_end.code(), idl::CONTROL_OUT_OF_RANGE) << past_end.Describe();

  const std::optional<int> status = replay.Wait(30s);
  ASSERT_TRUE(status && WIFEXITED(*status) && WEXITSTATUS(*status) == 0) << replay.Log();
  EXPECT_NE(replay.Log().find("3 seeks"), std::string::npos) << replay.Log();
  wait_for([] { return true; });
  const auto runs = Runs(seen);
  ASSERT_EQ(runs.size(), 3u) << Show(seen);
  EXPECT_EQ(runs[0].back(), paused_at) << Show(seen);  // nothing after the pause's sim time until the seek back
  EXPECT_EQ(runs[1].front(), 50 * kMs) << Show(seen);
  EXPECT_LT(runs[1].back(), 900 * kMs) << Show(seen);
  EXPECT_EQ(runs[2].front(), 900 * kMs) << Show(seen);
  EXPECT_LT(runs[2].back(), 1000 * kMs) << Show(seen);  // the seek past the end skipped the rest
}

}  // namespace
}  // namespace turf::test
