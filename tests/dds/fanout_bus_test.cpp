// dds::FanoutBus (dds/fanout_bus.h): one bus over two. Over two MemoryBuses (no DDS): a write reaches the readers
// of both, a reader takes from both, each sample once, Matched() adds up, latched samples reach late readers. One
// test over a real Participant on a private domain: a remote participant and an in-process reader both see the
// fanout's samples, and the fanout's reader gets each side's sample once.
#include <gtest/gtest.h>
#include <turf/idl/ClockPubSubTypes.h>
#include <turf/idl/SimControlPubSubTypes.h>
#include <turf/idl/SslVisionPubSubTypes.h>
#include <turf/idl/WorldStatePubSubTypes.h>
#include <unistd.h>

#include <chrono>
#include <functional>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "dds/fanout_bus.h"
#include "dds/memory_bus.h"
#include "dds/participant.h"
#include "tests/test_domain.h"

namespace turf {
namespace {

using namespace std::chrono_literals;
using SteadyClock = std::chrono::steady_clock;

idl::Clock ClockAt(uint64_t frame) {
  idl::Clock c;
  c.frame(frame);
  return c;
}

idl::SimControl Request(const std::string& client, uint64_t id) {
  idl::SimControl c;
  c.client(client);
  c.request_id(id);
  return c;
}

// Polls `done` until it answers true or 10 s pass.
bool WaitFor(const std::function<bool()>& done) {
  const auto end = SteadyClock::now() + 10s;
  while (SteadyClock::now() < end) {
    if (done()) return true;
    std::this_thread::sleep_for(2ms);
  }
  return done();
}

// Two memory buses and a fanout over them; the tests' common ground.
class FanoutBusTest : public ::testing::Test {
 protected:
  dds::MemoryBus a{"test"};
  dds::MemoryBus b{"test"};
  dds::FanoutBus fanout{a, b};
};

TEST_F(FanoutBusTest, AWriteReachesTheReadersOfBothBusesOnce) {
  auto on_a = a.MakeReader(dds::Topic::kClock);
  auto on_b = b.MakeReader(dds::Topic::kClock);
  auto writer = fanout.MakeWriter(dds::Topic::kClock);
  EXPECT_EQ(writer->Matched(), 2);

  EXPECT_TRUE(writer->Write(ClockAt(3)));
  std::vector<idl::Clock> got;
  ASSERT_TRUE(on_a->Take(&got));
  ASSERT_EQ(got.size(), 1u);
  EXPECT_EQ(got[0].frame(), 3u);
  ASSERT_TRUE(on_b->Take(&got));
  ASSERT_EQ(got.size(), 1u);
  EXPECT_EQ(got[0].frame(), 3u);
}

TEST_F(FanoutBusTest, AReaderTakesFromBothBusesEachSampleOnce) {
  int woken = 0;
  auto reader = fanout.MakeReader(dds::Topic::kControl, [&] { ++woken; });
  auto from_a = a.MakeWriter(dds::Topic::kControl);
  auto from_b = b.MakeWriter(dds::Topic::kControl);
  EXPECT_EQ(reader->Matched(), 2);
  EXPECT_EQ(from_a->Matched(), 1);

  from_a->Write(Request("remote", 1));
  from_b->Write(Request("local", 2));
  EXPECT_EQ(woken, 2);
  std::vector<idl::SimControl> got;
  ASSERT_TRUE(reader->Take(&got));
  ASSERT_EQ(got.size(), 2u);
  EXPECT_EQ(got[0].client(), "remote");
  EXPECT_EQ(got[1].client(), "local");
  EXPECT_FALSE(reader->Take(&got));
}

// The front-end's side and the remote side do not see each other's samples through the fanout: only the fanout's
// own endpoints span both.
TEST_F(FanoutBusTest, EndpointsOnOneSideDoNotReachTheOther) {
  dds::MemoryBus& remote = a;
  dds::MemoryBus& local = b;
  auto node_reader = fanout.MakeReader(dds::Topic::kControl);
  auto remote_reader = remote.MakeReader(dds::Topic::kControl);
  auto local_writer = local.MakeWriter(dds::Topic::kControl);
  local_writer->Write(Request("local", 1));
  std::vector<idl::SimControl> got;
  EXPECT_TRUE(node_reader->Take(&got));
  EXPECT_FALSE(remote_reader->Take(&got));
}

TEST_F(FanoutBusTest, LatchedSamplesReachLateReadersOnEitherSide) {
  auto writer = fanout.MakeWriter(dds::Topic::kSslField);
  idl::SslField field;
  field.robots_per_team(11);
  writer->Write(field);
  auto late = b.MakeReader(dds::Topic::kSslField);
  std::vector<idl::SslField> got;
  ASSERT_TRUE(late->Take(&got));
  EXPECT_EQ(got.back().robots_per_team(), 11);
  auto late_fanout = fanout.MakeReader(dds::Topic::kSslField);
  ASSERT_TRUE(late_fanout->Take(&got));
  EXPECT_EQ(got.size(), 2u);  // the one writer's sample, kept on each bus: a reader on both sees it once per bus
}

TEST(FanoutBus, RefusesBusesWithDifferentPrefixes) {
  dds::MemoryBus a("one"), b("two");
  EXPECT_THROW(dds::FanoutBus(a, b), std::invalid_argument);
}

TEST_F(FanoutBusTest, ListsItsTopicsOnItselfAndOnBothBuses) {
  auto writer = fanout.MakeWriter(dds::Topic::kWorldState);
  auto reader = fanout.MakeReader(dds::Topic::kControl);
  EXPECT_EQ(fanout.Endpoints().size(), 2u);
  EXPECT_EQ(a.Endpoints(), fanout.Endpoints());
  EXPECT_EQ(b.Endpoints(), fanout.Endpoints());
  EXPECT_NE(fanout.Describe().find("in-memory"), std::string::npos);
}

// turf-sim's arrangement: the fanout over a DDS participant and a MemoryBus; a remote participant on the domain.
TEST(FanoutBus, OverDdsAndMemoryRemoteAndLocalBothSeeTheSamplesAndAreHeardOnce) {
  dds::ParticipantOptions o;
  o.domain = test::TestDomain(53);
  o.prefix = "fanout" + std::to_string(getpid());
  o.qos_file = TURF_SOURCE_DIR "/configs/qos/turf_qos.xml";
  o.name = "node";
  dds::Participant dds_side(o);
  dds::MemoryBus local(o.prefix);
  dds::FanoutBus fanout(dds_side, local);
  auto state_writer = fanout.MakeWriter(dds::Topic::kWorldState);
  auto control_reader = fanout.MakeReader(dds::Topic::kControl);

  o.name = "remote";
  dds::Participant remote(o);
  auto remote_state = remote.MakeReader(dds::Topic::kWorldState);
  auto remote_control = remote.MakeWriter(dds::Topic::kControl);
  auto local_state = local.MakeReader(dds::Topic::kWorldState);
  auto local_control = local.MakeWriter(dds::Topic::kControl);
  // Both ends of each DDS match: a reader that has matched a writer does not mean the writer has matched it (a
  // volatile sample written before that is lost: the loaded soak's flake).
  ASSERT_TRUE(WaitFor([&] {
    return state_writer->Matched() == 2 && control_reader->Matched() == 2 && remote_control->Matched() == 1 &&
           remote_state->Matched() == 1;
  }));

  idl::WorldState state;
  state.frame(42);
  state_writer->Write(state);
  std::vector<idl::WorldState> states;
  ASSERT_TRUE(local_state->Take(&states));  // at once
  EXPECT_EQ(states.back().frame(), 42u);
  ASSERT_TRUE(WaitFor([&] { return remote_state->Take(&states); }));
  EXPECT_EQ(states.back().frame(), 42u);

  remote_control->Write(Request("remote", 1));
  local_control->Write(Request("local", 2));
  std::vector<idl::SimControl> got, all;
  ASSERT_TRUE(WaitFor([&] {
    if (control_reader->Take(&got)) all.insert(all.end(), got.begin(), got.end());
    return all.size() >= 2;
  }));
  // A later marker from the remote side: anything duplicated would have arrived before it.
  remote_control->Write(Request("remote", 3));
  ASSERT_TRUE(WaitFor([&] {
    if (control_reader->Take(&got)) all.insert(all.end(), got.begin(), got.end());
    return !all.empty() && all.back().request_id() == 3;
  }));
  ASSERT_EQ(all.size(), 3u);
  int remote_seen = 0, local_seen = 0;
  for (const idl::SimControl& c : all) (c.client() == "remote" ? remote_seen : local_seen)++;
  EXPECT_EQ(remote_seen, 2);
  EXPECT_EQ(local_seen, 1);
}

}  // namespace
}  // namespace turf
