// sim.publish(domain=...) seen from another process: a Sim stepped by Python (publish_child.py) publishes its
// topics on a DDS domain; this test's reader gets world states whose every number is, bit for bit, what the
// Python caller's step() returned at the same frame, the clock that goes with them and the latched field.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <turf/idl/ClockPubSubTypes.h>
#include <turf/idl/SslVisionPubSubTypes.h>
#include <turf/idl/WorldStatePubSubTypes.h>
#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <string>
#include <vector>

#include "dds/participant.h"
#include "tests/support/process.h"
#include "tests/support/wake_wait.h"
#include "tests/test_domain.h"

namespace turf::test {
namespace {

using namespace std::chrono_literals;

constexpr int kCalls = 30;
constexpr int kStepsPerCall = 8;

// One step() call's observation as the child wrote it.
struct Returned {
  double ball[6];
  std::vector<double> robots;  // robots x 9: x, y, yaw, vx, vy, omega, on_field, ball_contact, kick_count
};

std::map<uint64_t, Returned> ReadRecords(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::map<uint64_t, Returned> out;
  if (bytes.size() < 4) return out;
  uint32_t robots = 0;
  std::memcpy(&robots, bytes.data(), 4);
  const size_t record = 8 + 6 * 8 + static_cast<size_t>(robots) * 9 * 8;
  for (size_t at = 4; at + record <= bytes.size(); at += record) {
    uint64_t frame = 0;
    std::memcpy(&frame, bytes.data() + at, 8);
    Returned r;
    std::memcpy(r.ball, bytes.data() + at + 8, sizeof r.ball);
    r.robots.resize(static_cast<size_t>(robots) * 9);
    std::memcpy(r.robots.data(), bytes.data() + at + 8 + sizeof r.ball, r.robots.size() * 8);
    out[frame] = r;
  }
  return out;
}

// The same bits, not merely equal values (so -0.0 against 0.0 or a NaN would show).
bool Same(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

void ExpectSameState(const idl::WorldState& s, const Returned& r) {
  const double ball[6] = {s.ball().position().x(), s.ball().position().y(), s.ball().position().z(),
                          s.ball().velocity().x(), s.ball().velocity().y(), s.ball().velocity().z()};
  for (int i = 0; i < 6; ++i) EXPECT_TRUE(Same(ball[i], r.ball[i])) << "frame " << s.frame() << " ball column " << i;
  ASSERT_EQ(s.robots().size() * 9, r.robots.size());
  for (size_t i = 0; i < s.robots().size(); ++i) {
    const idl::RobotState& o = s.robots()[i];
    const double* row = &r.robots[i * 9];
    const double got[7] = {o.position().x(),        o.position().y(),        o.yaw(),
                           o.linear_velocity().x(), o.linear_velocity().y(), o.angular_velocity().z(),
                           o.on_field() ? 1.0 : 0.0};
    for (int c = 0; c < 7; ++c)
      EXPECT_TRUE(Same(got[c], row[c])) << "frame " << s.frame() << " robot " << i << " column " << c;
  }
}

TEST(PythonPublish, AReaderSeesTheStatesStepReturnedBitForBit) {
  dds::ParticipantOptions o;
  o.domain = TestDomain(31);
  o.prefix = "pypub" + std::to_string(getpid());
  o.name = "publish_test";
  o.qos_file = TURF_SOURCE_DIR "/configs/qos/turf_qos.xml";
  const std::string out = LogDir() + "/publish_child_" + std::to_string(getpid()) + ".bin";
  std::remove(out.c_str());

  std::map<uint64_t, idl::WorldState> states;
  std::vector<idl::Clock> clocks;
  bool field = false;
  {
    WakeWait wake;
    dds::Participant participant(o);
    auto state_reader = participant.MakeReader(dds::Topic::kWorldState, [&] { wake.Wake(); });
    auto clock_reader = participant.MakeReader(dds::Topic::kClock, [&] { wake.Wake(); });
    auto field_reader = participant.MakeReader(dds::Topic::kSslField, [&] { wake.Wake(); });
    Process child(
        "publish_child",
        {TURF_PYTHON, TURF_SOURCE_DIR "/tests/python/publish_child.py", "--domain", std::to_string(o.domain),
         "--prefix", o.prefix, "--out", out, "--calls", std::to_string(kCalls), "--n", std::to_string(kStepsPerCall)},
        {{"PYTHONPATH", TURF_PYTHON_DIR}});
    const uint64_t last_frame = kCalls * kStepsPerCall;
    std::vector<idl::WorldState> taken;
    std::vector<idl::Clock> clocks_taken;
    std::vector<idl::SslField> fields;
    const bool got_last = wake.Until(std::chrono::steady_clock::now() + 90s, [&] {
      if (state_reader->Take(&taken))
        for (const idl::WorldState& s : taken) states[s.frame()] = s;
      if (clock_reader->Take(&clocks_taken)) clocks.insert(clocks.end(), clocks_taken.begin(), clocks_taken.end());
      if (field_reader->Take(&fields)) field = true;
      // The latched field comes from another writer: it may arrive after the last state.
      return (states.count(last_frame) > 0 && field) || !child.Running();
    });
    ASSERT_TRUE(got_last) << "no world state of frame " << last_frame << "; child log:\n" << child.Log();
    // Leaving the domain tells the child its last state arrived; it then writes what step() returned and ends.
    state_reader.reset();
    clock_reader.reset();
    field_reader.reset();
    const std::optional<int> status = child.Wait(120s);
    ASSERT_TRUE(status.has_value()) << child.Log();
    ASSERT_TRUE(WIFEXITED(*status) && WEXITSTATUS(*status) == 0) << child.Log();
  }
  const std::map<uint64_t, Returned> returned = ReadRecords(out);
  const uint64_t last_frame = kCalls * kStepsPerCall;
  ASSERT_EQ(returned.size(), static_cast<size_t>(kCalls));
  EXPECT_TRUE(field) << "no ssl/field (latched)";
  int compared = 0;
  for (const auto& [frame, state] : states) {
    const auto it = returned.find(frame);
    if (it == returned.end()) continue;  // a state due between two step() calls (100 Hz of sim time)
    ExpectSameState(state, it->second);
    ++compared;
  }
  // Every step() call's state is published, but a reliable KEEP_LAST(8) writer may replace a sample before this
  // reader has it while Python steps this fast: the last one always arrives.
  EXPECT_GE(compared, 1);
  EXPECT_TRUE(returned.count(last_frame) > 0 && states.count(last_frame) > 0);
  // The clock goes with the states: lockstep, the frame of a published state, sim time = frame x step.
  ASSERT_FALSE(clocks.empty());
  EXPECT_EQ(clocks.back().frame(), last_frame);
  EXPECT_EQ(clocks.back().mode(), idl::TIME_LOCKSTEP);
  EXPECT_EQ(clocks.back().sim_time_ns(), states.at(last_frame).sim_time_ns());
  std::printf("compared %d of %zu world states received with step()'s observations\n", compared, states.size());
}

}  // namespace
}  // namespace turf::test
