// turf replay --resimulate: a match run free in this process (turf-sim's node and turf-record's recorder on one
// MemoryBus, the test writing scripted commands whenever it wakes, so the step at which each lands depends on
// thread timing) is recorded, then re-simulated from the file alone: every recorded output comes out byte for
// byte. One applied input changed in the file: the first difference is named, at or after that input's time.
#include <gtest/gtest.h>
#include <turf/idl/ClockPubSubTypes.h>
#include <turf/idl/JointsPubSubTypes.h>
#include <turf/idl/SimControlPubSubTypes.h>
#include <turf/idl/SimRecordPubSubTypes.h>
#include <turf/idl/SslRobotPubSubTypes.h>

#include <unistd.h>

#include <atomic>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <thread>
#include <tuple>
#include <vector>

#include "codecs/mcap/reader.h"
#include "codecs/mcap/writer.h"
#include "dds/memory_bus.h"
#include "loader/legged_scene_yaml.h"
#include "loader/realism_yaml.h"
#include "loader/scene_yaml.h"
#include "loader/text_file.h"
#include "participants/common/mcap_file.h"
#include "participants/recorder/recorder.h"
#include "participants/replay/resimulate.h"
#include "participants/sim/cdr.h"
#include "participants/sim/sim_node.h"
#include "tests/support/wake_wait.h"

namespace turf {
namespace {

using SteadyClock = std::chrono::steady_clock;

std::string ScenePath(const std::string& name) { return std::string(TURF_SOURCE_DIR) + "/configs/scenes/" + name; }

std::string TempFile(const std::string& name) {
  return (std::filesystem::temp_directory_path() / (name + "." + std::to_string(::getpid()) + ".mcap")).string();
}

SceneSource SourceOf(const std::string& path, const std::string& kind, const std::string& name, uint64_t seed,
                     const std::string& realism) {
  SceneSource s{kind, name, path, std::filesystem::path(path).parent_path().string(), "", realism, seed};
  std::string error;
  if (!ReadTextFile(path, 1u << 20, &s.yaml, &error)) throw std::runtime_error(error);
  return s;
}

// What the test writes whenever it sees the simulation at `sim_time_ns` (its `round`-th wake-up); made on the
// match's bus, destroyed before it.
class Script {
 public:
  virtual ~Script() = default;
  virtual void At(int64_t sim_time_ns, int round) = 0;
};
using MakeScript = std::function<std::unique_ptr<Script>(dds::Bus& bus)>;

struct Recorded {
  RecorderTotals totals;
  int rounds = 0;
};

// Runs `scene` free for `duration` s of sim time on a MemoryBus with turf-record's recorder into `file`, and the
// script on this thread at every clock sample it wakes up to.
template <class SceneKind>
Recorded RecordMatch(SceneKind scene, const SceneSource& source, double duration, const std::string& file,
                     const MakeScript& make_script, TimeMode mode = TimeMode::kFreeRunning) {
  dds::MemoryBus bus;
  RecorderOptions ro;
  ro.file = file;
  ro.progress_interval_s = 1e6;
  auto recorder = std::make_unique<Recorder>(ro, bus);
  std::atomic<bool> recorder_stop{false};
  std::thread recording([&] { recorder->Run([&] { return recorder_stop.load(); }); });

  test::WakeWait wake;
  std::vector<idl::Clock> clocks;
  auto clock_reader = bus.MakeReader(dds::Topic::kClock, [&wake] { wake.Wake(); });
  const std::unique_ptr<Script> script = make_script(bus);
  SimNodeOptions options;
  options.mode = mode;
  options.duration = duration;
  options.scene_source = source;
  SimNode node(std::move(scene), options, bus);
  std::atomic<bool> done{false};
  std::thread running([&] {
    node.Run([] { return false; });
    done = true;
    wake.Wake();
  });
  Recorded out;
  const auto deadline = SteadyClock::now() + std::chrono::seconds(600);
  while (!done.load()) {
    int64_t newest = -1;
    wake.Until(deadline, [&] {
      if (clock_reader->Take(&clocks)) newest = clocks.back().sim_time_ns();
      return newest >= 0 || done.load();
    });
    if (newest >= 0 && !done.load()) script->At(newest, out.rounds++);
    if (SteadyClock::now() >= deadline) break;
  }
  running.join();
  recorder_stop = true;
  recording.join();
  out.totals = recorder->totals();
  return out;
}

// Scripted SSL play: every robot of both teams driven along a curve that changes with sim time, kicks now and
// then, the ball teleported at 5 s and 12 s.
class SslScript final : public Script {
 public:
  explicit SslScript(dds::Bus& bus)
      : writers_{bus.MakeWriter(dds::Topic::kSslCommandBlue), bus.MakeWriter(dds::Topic::kSslCommandYellow)},
        control_(bus.MakeWriter(dds::Topic::kControl)) {}

  void At(int64_t t_ns, int round) override {
    const double t = static_cast<double>(t_ns) * 1e-9;
    for (int team = 0; team < 2; ++team) {
      for (int id = 0; id < 6; ++id) {
        idl::SslRobotCommand c;
        c.team(team == 0 ? idl::TEAM_BLUE : idl::TEAM_YELLOW);
        c.id(static_cast<uint8_t>(id));
        c.move(idl::MOVE_LOCAL_VELOCITY);
        c.velocity().x(1.2 * std::sin(0.7 * t + id));
        c.velocity().y(0.6 * std::cos(0.5 * t + team));
        c.velocity().z(1.5 * std::sin(0.3 * t + id * team));
        if ((round + id) % 40 == 0) {
          c.kick(idl::KICK_FLAT);
          c.kick_speed(4.0);
        }
        c.dribbler_speed(id % 2 == 0 ? 300.0 : 0.0);
        writers_[team]->Write(c);
      }
    }
    const int64_t teleport_at[] = {5'000'000'000, 12'000'000'000};
    if (teleports_ < 2 && t_ns >= teleport_at[teleports_]) {
      idl::SimControl req;
      req.client("resimulate_test");
      req.request_id(static_cast<uint64_t>(++teleports_));
      req.op(idl::OP_TELEPORT_BALL);
      req.ball().position().x(teleports_ == 1 ? 1.0 : -2.0);
      req.ball().position().y(0.5);
      req.ball().velocity().x(-2.0);
      control_->Write(req);
    }
  }

 private:
  std::unique_ptr<dds::Writer<idl::SslRobotCommandPubSubType>> writers_[2];
  std::unique_ptr<dds::Writer<idl::SimControlPubSubType>> control_;
  int teleports_ = 0;
};

// A lockstep driver (as the simulation protocol's sync port): at each clock it wakes to, one STEP of 4 frames
// carrying every blue robot's command; the ball teleported once.
class LockstepScript final : public Script {
 public:
  explicit LockstepScript(dds::Bus& bus) : control_(bus.MakeWriter(dds::Topic::kControl)) {}

  void At(int64_t t_ns, int round) override {
    const double t = static_cast<double>(t_ns) * 1e-9;
    idl::SimControl step;
    step.client("resimulate_test");
    step.request_id(static_cast<uint64_t>(round) + 1);
    step.op(idl::OP_STEP);
    step.step_count(4);
    for (int id = 0; id < 6; ++id) {
      idl::SslRobotCommand c;
      c.team(idl::TEAM_BLUE);
      c.id(static_cast<uint8_t>(id));
      c.move(idl::MOVE_LOCAL_VELOCITY);
      c.velocity().x(std::sin(t + id));
      c.velocity().z(0.5 * std::cos(t));
      step.commands().push_back(c);
    }
    if (round == 50) {
      idl::SimControl teleport;
      teleport.client("resimulate_test");
      teleport.request_id(1'000'000);
      teleport.op(idl::OP_TELEPORT_BALL);
      teleport.ball().position().x(-1.0);
      control_->Write(teleport);
    }
    control_->Write(step);
  }

 private:
  std::unique_ptr<dds::Writer<idl::SimControlPubSubType>> control_;
};

struct File {
  mcap::FileInfo info;
  std::vector<std::tuple<uint16_t, uint32_t, uint64_t, uint64_t, std::string>> messages;
};

File ReadAll(const std::string& path) {
  File f;
  McapFileSource source(path);
  EXPECT_TRUE(source.ok());
  const mcap::Damage d = mcap::Scan(source, {}, &f.info, [&](const mcap::Channel& c, const mcap::Message& m) {
    f.messages.emplace_back(c.id, m.sequence, m.log_time, m.publish_time, std::string(m.data));
  });
  EXPECT_TRUE(d.ok()) << d.Describe();
  return f;
}

void WriteAll(const File& f, const std::string& path) {
  McapFileSink sink(path);
  mcap::Writer writer(&sink, {});
  std::map<uint16_t, uint16_t> schema_ids, channel_ids;
  for (const auto& [id, s] : f.info.schemas) schema_ids[id] = writer.AddSchema(s.name, s.encoding, s.data);
  for (const auto& [id, c] : f.info.channels)
    channel_ids[id] = writer.AddChannel(schema_ids[c.schema_id], c.topic, c.message_encoding, c.metadata);
  for (const auto& [channel, sequence, log_time, publish_time, data] : f.messages)
    writer.Write(channel_ids[channel], sequence, log_time, publish_time, data);
  writer.Close();
  sink.Flush();
}

uint16_t ChannelOf(const File& f, const std::string& suffix) {
  for (const auto& [id, c] : f.info.channels)
    if (c.topic.size() >= suffix.size() && c.topic.compare(c.topic.size() - suffix.size(), suffix.size(), suffix) == 0)
      return id;
  return 0;
}

class Resimulation : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    SceneLoadResult loaded = LoadSceneFile(ScenePath("ssl_div_a.yaml"));
    ASSERT_TRUE(loaded.scene);
    const RealismLoadResult realism = LoadRealism("realistic");
    ASSERT_TRUE(realism.realism);
    loaded.scene->realism = *realism.realism;
    const SceneSource source =
        SourceOf(ScenePath("ssl_div_a.yaml"), "ssl", loaded.scene->name, loaded.scene->seed, "realistic");
    ssl_file_ = new std::string(TempFile("resim_ssl"));
    ssl_ = new Recorded(RecordMatch(std::move(*loaded.scene), source, 20.0, *ssl_file_,
                                    [](dds::Bus& bus) { return std::make_unique<SslScript>(bus); }));
  }
  static void TearDownTestSuite() {
    std::filesystem::remove(*ssl_file_);
    delete ssl_file_;
    delete ssl_;
  }
  static std::string* ssl_file_;
  static Recorded* ssl_;
};
std::string* Resimulation::ssl_file_ = nullptr;
Recorded* Resimulation::ssl_ = nullptr;

TEST_F(Resimulation, SslMatchWithNoiseAndCommandsIsReproducedByteForByte) {
  ASSERT_EQ(ssl_->totals.dropped, 0u) << "the recorder dropped samples; the comparison would be partial";
  ASSERT_GT(ssl_->rounds, 20) << "too few scripted command rounds";
  const ResimulateResult r = Resimulate({*ssl_file_}, [] { return false; });
  std::printf("%s\n", r.verdict.c_str());
  EXPECT_TRUE(r.identical) << r.verdict;
  EXPECT_GT(r.input_records, 20u);
  // 20 s of world states at 100 Hz, camera frames at 60 Hz, stats, feedback: every one of them.
  EXPECT_GT(r.recorded, 2000u + 1200u);
  EXPECT_EQ(r.reproduced, r.recorded) << r.verdict;
  EXPECT_GE(r.sim_time_ns, 20'000'000'000);
}

// A match started in lockstep (turf-sim --lockstep) took every step from a STEP request: re-simulated free-running,
// each was refused and nothing matched. The recorded clock's first sample says how it began.
TEST(ResimulationLockstep, AMatchStartedInLockstepIsReproducedByteForByte) {
  SceneLoadResult loaded = LoadSceneFile(ScenePath("ssl_div_a.yaml"));
  ASSERT_TRUE(loaded.scene);
  loaded.scene->realism = *LoadRealism("realistic").realism;
  const SceneSource source =
      SourceOf(ScenePath("ssl_div_a.yaml"), "ssl", loaded.scene->name, loaded.scene->seed, "realistic");
  const std::string file = TempFile("resim_lockstep");
  const Recorded recorded = RecordMatch(
      std::move(*loaded.scene), source, 3.0, file, [](dds::Bus& bus) { return std::make_unique<LockstepScript>(bus); },
      TimeMode::kLockstep);
  ASSERT_EQ(recorded.totals.dropped, 0u);
  ASSERT_GT(recorded.rounds, 100);
  const ResimulateResult r = Resimulate({file}, [] { return false; });
  std::printf("%s\n", r.verdict.c_str());
  EXPECT_TRUE(r.identical) << r.verdict;
  EXPECT_GT(r.input_records, 100u);
  EXPECT_GE(r.sim_time_ns, 2'900'000'000);
  std::filesystem::remove(file);
}

TEST_F(Resimulation, ChangedInputsAreReportedAtTheFirstOutputTheyChange) {
  File f = ReadAll(*ssl_file_);
  const uint16_t inputs = ChannelOf(f, "/sim/applied_inputs");
  ASSERT_NE(inputs, 0);
  // From the first applied-inputs record after 8 s of sim time that carries a blue command, every blue command of
  // ten such records goes the other way: one changed command alone may be lost on the realistic radio link (bursts)
  // or superseded by a newer one in the same poll, and then rightly changes nothing.
  int64_t changed_at = -1;
  int changed_records = 0;
  for (auto& [channel, sequence, log_time, publish_time, data] : f.messages) {
    if (channel != inputs || publish_time < 8'000'000'000ull || changed_records == 10) continue;
    idl::AppliedInputs record;
    ASSERT_TRUE(
        FromCdr<idl::AppliedInputsPubSubType>(reinterpret_cast<const uint8_t*>(data.data()), data.size(), &record));
    bool changed = false;
    for (idl::AppliedInput& in : record.inputs()) {
      if (in.topic() != "ssl/command/blue") continue;
      idl::SslRobotCommand c;
      ASSERT_TRUE(FromCdr<idl::SslRobotCommandPubSubType>(in.cdr().data(), in.cdr().size(), &c));
      c.velocity().x(c.velocity().x() > 0 ? -1.5 : 1.5);
      ASSERT_TRUE(ToCdr<idl::SslRobotCommandPubSubType>(c, &in.cdr()));
      changed = true;
    }
    if (!changed) continue;
    if (changed_at < 0) changed_at = record.sim_time_ns();
    ++changed_records;
    std::vector<uint8_t> bytes;
    ASSERT_TRUE(ToCdr<idl::AppliedInputsPubSubType>(record, &bytes));
    data.assign(bytes.begin(), bytes.end());
  }
  ASSERT_GE(changed_at, 0) << "no blue command after 8 s";
  const std::string altered = TempFile("resim_altered");
  WriteAll(f, altered);
  const ResimulateResult r = Resimulate({altered}, [] { return false; });
  std::printf("%s (the changed inputs from sim time %.6f s)\n", r.verdict.c_str(), changed_at * 1e-9);
  std::filesystem::remove(altered);
  EXPECT_FALSE(r.identical);
  EXPECT_NE(r.topic, "sim/applied_inputs") << r.verdict;  // the changed record is re-published as it is in the file
  // Nothing before the changed input differs; the robot's changed motion shows within half a second (the realistic
  // command link's latency and a camera's processing delay are tens of ms).
  EXPECT_GE(r.diff_sim_time_ns, changed_at) << r.verdict;
  EXPECT_LT(r.diff_sim_time_ns, changed_at + 500'000'000) << r.verdict;
  EXPECT_NE(r.verdict.find("first differing byte at offset"), std::string::npos) << r.verdict;
}

// A file's times are untrusted: a world state copied to sim time 9e18 ns, or the last applied-inputs record moved to
// a step no recording reaches, ends the re-simulation a second past the recording's outputs, not years later, and
// the verdict names what was not reproduced.
TEST_F(Resimulation, AForgedTimeOrStepFarPastTheRecordingEndsTheRunAtItsOutputs) {
  const File original = ReadAll(*ssl_file_);
  const uint16_t world = ChannelOf(original, "/world_state");
  const uint16_t inputs = ChannelOf(original, "/sim/applied_inputs");
  ASSERT_NE(world, 0);
  ASSERT_NE(inputs, 0);

  File far = original;
  for (const auto& m : original.messages) {
    if (std::get<0>(m) != world) continue;
    auto copy = m;
    std::get<3>(copy) = 9'000'000'000'000'000'000ull;
    far.messages.push_back(copy);
    break;
  }
  const std::string far_file = TempFile("resim_far");
  WriteAll(far, far_file);
  const ResimulateResult a = Resimulate({far_file}, [] { return false; });
  std::filesystem::remove(far_file);
  std::printf("%s\n", a.verdict.c_str());
  EXPECT_FALSE(a.identical);
  EXPECT_EQ(a.topic, "world_state") << a.verdict;
  EXPECT_EQ(a.diff_sim_time_ns, 9'000'000'000'000'000'000) << a.verdict;
  EXPECT_EQ(a.reproduced + 1, a.recorded) << a.verdict;  // everything else is reproduced
  EXPECT_LT(a.sim_time_ns, 23'000'000'000) << a.verdict;

  File late = original;
  for (auto it = late.messages.rbegin(); it != late.messages.rend(); ++it) {
    if (std::get<0>(*it) != inputs) continue;
    std::string& data = std::get<4>(*it);
    idl::AppliedInputs record;
    ASSERT_TRUE(
        FromCdr<idl::AppliedInputsPubSubType>(reinterpret_cast<const uint8_t*>(data.data()), data.size(), &record));
    record.step(uint64_t{1} << 62);
    std::vector<uint8_t> bytes;
    ASSERT_TRUE(ToCdr<idl::AppliedInputsPubSubType>(record, &bytes));
    data.assign(bytes.begin(), bytes.end());
    break;
  }
  const std::string late_file = TempFile("resim_late_step");
  WriteAll(late, late_file);
  const ResimulateResult b = Resimulate({late_file}, [] { return false; });
  std::filesystem::remove(late_file);
  std::printf("%s\n", b.verdict.c_str());
  EXPECT_FALSE(b.identical);
  EXPECT_NE(b.verdict.find("with 1 of"), std::string::npos) << b.verdict;
  EXPECT_NE(b.verdict.find("the next one is past the recording's outputs"), std::string::npos) << b.verdict;
  EXPECT_LT(b.sim_time_ns, 23'000'000'000) << b.verdict;
}

// A Booster T1 standing, its head and arms driven by scripted joint commands.
class T1Script final : public Script {
 public:
  explicit T1Script(dds::Bus& bus) : writer_(bus.MakeWriter(dds::Topic::kRobotJointCommand)) {}

  void At(int64_t t_ns, int /*round*/) override {
    const double t = static_cast<double>(t_ns) * 1e-9;
    idl::JointCommand c;
    c.robot("t1");
    const std::pair<const char*, double> targets[] = {{"AAHead_yaw", 0.5 * std::sin(t)},
                                                      {"Left_Shoulder_Pitch", 0.6 * std::sin(1.3 * t)},
                                                      {"Right_Shoulder_Pitch", -0.6 * std::sin(0.9 * t)}};
    for (const auto& [name, q] : targets) {
      idl::JointTarget j;
      j.name(name);
      j.mode(idl::JOINT_POSITION);
      j.value(q);
      j.kp(-1);
      j.kd(-1);
      c.joints().push_back(j);
    }
    writer_->Write(c);
  }

 private:
  std::unique_ptr<dds::Writer<idl::JointCommandPubSubType>> writer_;
};

TEST(ResimulationLegged, T1WithJointCommandsIsReproducedByteForByte) {
  LeggedSceneLoadResult loaded = LoadLeggedSceneFile(ScenePath("t1_stand.yaml"));
  ASSERT_TRUE(loaded.scene);
  const RealismLoadResult realism = LoadRealism("realistic");  // encoder and IMU noise, the sensor links
  ASSERT_TRUE(realism.realism);
  loaded.scene->realism = *realism.realism;
  const SceneSource source =
      SourceOf(ScenePath("t1_stand.yaml"), "legged", loaded.scene->name, loaded.scene->seed, "realistic");
  const std::string file = TempFile("resim_t1");
  const Recorded rec = RecordMatch(std::move(*loaded.scene), source, 20.0, file,
                                   [](dds::Bus& bus) { return std::make_unique<T1Script>(bus); });
  ASSERT_EQ(rec.totals.dropped, 0u);
  ASSERT_GT(rec.rounds, 20);
  const ResimulateResult r = Resimulate({file}, [] { return false; });
  std::printf("%s\n", r.verdict.c_str());
  std::filesystem::remove(file);
  EXPECT_TRUE(r.identical) << r.verdict;
  EXPECT_GT(r.input_records, 20u);
  EXPECT_GT(r.recorded, 4000u);  // robots/state, joint states, IMU, forces, links at 200 Hz for 20 s
  EXPECT_EQ(r.reproduced, r.recorded) << r.verdict;
}

}  // namespace
}  // namespace turf
