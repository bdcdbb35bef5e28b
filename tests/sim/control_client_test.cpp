// The one control client (dds/control_client.h) against an in-process turf-sim
// node, and against a fake server that never answers or answers garbage.
// Every wait is for a condition with a deadline; physics is measured in frames.
#include "dds/control_client.h"

#include <cmath>
#include <limits>
#include <map>
#include <vector>

#include "participants/common/wakeup.h"
#include "tests/sim/sim_harness.h"

namespace turf::test {
namespace {

constexpr auto kCall = std::chrono::seconds(15);  // generous: a loaded machine discovers slowly

// A client of its own (its own participant), as a separate process would be.
struct ClientUnderTest {
  explicit ClientUnderTest(const dds::ParticipantOptions& o, const std::string& name)
      : participant(o), client(participant, name, [this] { wakeup.Notify(); }) {}
  Wakeup wakeup;
  dds::Participant participant;
  dds::ControlClient client;
};

idl::SimControl BallAt(double x, double y) {
  idl::SimControl c = Op(idl::OP_TELEPORT_BALL);
  c.ball().position().x(x);
  c.ball().position().y(y);
  c.ball().position().z(0.0215);
  return c;
}

idl::SimControl RealismPreset(const std::string& name) {
  idl::SimControl c = Op(idl::OP_SET_REALISM);
  c.realism_preset(name);
  return c;
}

idl::SimControl Step(uint32_t n) {
  idl::SimControl c = Op(idl::OP_STEP);
  c.step_count(n);
  return c;
}

TEST(ControlClient, RepliesMatchTheirRequestsAmongInterleavedClients) {
  const auto dds = UniqueDds("sim");
  SimUnderTest sim(test::OneRobot(), dds, TimeMode::kFreeRunning);
  ClientUnderTest a(dds, "client-a");
  ClientUnderTest b(dds, "client-b");
  const auto deadline = Clock::now() + kCall;
  ASSERT_TRUE(a.client.WaitForServer(deadline));
  ASSERT_TRUE(b.client.WaitForServer(deadline));
  const dds::ControlOutcome paused = a.client.Call(Op(idl::OP_PAUSE), kCall);
  ASSERT_TRUE(paused.ok()) << paused.Describe();

  // Interleaved on the wire: a, b, a, b; each asks something with its own answer.
  const uint64_t a1 = a.client.Send(BallAt(1.0, 0.5), kCall);
  const uint64_t b1 = b.client.Send(BallAt(std::nan(""), 0.0), kCall);
  const uint64_t a2 = a.client.Send(RealismPreset("no_such_preset"), kCall);
  const uint64_t b2 = b.client.Send(Step(10), kCall);

  const dds::ControlOutcome ra2 = a.client.Wait(a2);  // out of order on purpose
  const dds::ControlOutcome rb2 = b.client.Wait(b2);
  const dds::ControlOutcome ra1 = a.client.Wait(a1);
  const dds::ControlOutcome rb1 = b.client.Wait(b1);

  ASSERT_TRUE(ra1.reply && rb1.reply && ra2.reply && rb2.reply)
      << ra1.Describe() << " / " << rb1.Describe() << " / " << ra2.Describe() << " / " << rb2.Describe();
  EXPECT_EQ(ra1.reply->client(), "client-a");
  EXPECT_EQ(ra1.reply->request_id(), a1);
  EXPECT_EQ(ra1.reply->op(), idl::OP_TELEPORT_BALL);
  EXPECT_TRUE(ra1.ok()) << ra1.Describe();
  EXPECT_EQ(rb1.reply->client(), "client-b");
  EXPECT_EQ(rb1.reply->request_id(), b1);
  EXPECT_EQ(rb1.error, dds::ControlCallError::kRefused);
  EXPECT_EQ(rb1.code(), idl::CONTROL_NOT_FINITE);
  EXPECT_EQ(ra2.reply->request_id(), a2);
  EXPECT_EQ(ra2.reply->op(), idl::OP_SET_REALISM);
  EXPECT_EQ(ra2.code(), idl::CONTROL_UNKNOWN_PRESET);
  EXPECT_EQ(rb2.reply->request_id(), b2);
  EXPECT_EQ(rb2.reply->op(), idl::OP_STEP);
  EXPECT_TRUE(rb2.ok()) << rb2.Describe();
  // Paused: the step's reply comes at the frame its 10 steps reached.
  EXPECT_EQ(rb2.reply->frame(), paused.reply->frame() + 10);
  // Each saw only its own replies: none stray, none malformed.
  EXPECT_EQ(a.client.stray_replies(), 0u);
  EXPECT_EQ(b.client.stray_replies(), 0u);
  EXPECT_EQ(a.client.bad_replies(), 0u);
}

TEST(ControlClient, RefusalsCarryTheirCode) {
  const auto dds = UniqueDds("sim");
  SimUnderTest sim(test::OneRobot(), dds, TimeMode::kFreeRunning);
  ClientUnderTest t(dds, "codes");
  ASSERT_TRUE(t.client.WaitForServer(Clock::now() + kCall));

  // STEP while running: not allowed.
  dds::ControlOutcome o = t.client.Call(Step(1), kCall);
  EXPECT_EQ(o.error, dds::ControlCallError::kRefused) << o.Describe();
  EXPECT_EQ(o.code(), idl::CONTROL_NOT_ALLOWED) << o.Describe();

  o = t.client.Call(BallAt(std::numeric_limits<double>::infinity(), 0.0), kCall);
  EXPECT_EQ(o.code(), idl::CONTROL_NOT_FINITE) << o.Describe();
  o = t.client.Call(BallAt(100.0, 0.0), kCall);
  EXPECT_EQ(o.code(), idl::CONTROL_OUTSIDE_FIELD) << o.Describe();
  idl::SimControl realism = Op(idl::OP_SET_REALISM);
  idl::RealismValue vanish;
  vanish.parameter(idl::REALISM_CAMERA_ROBOT_VANISH);
  vanish.value(1.5);
  realism.realism_values({vanish});
  o = t.client.Call(realism, kCall);
  EXPECT_EQ(o.code(), idl::CONTROL_OUT_OF_RANGE) << o.Describe();
  EXPECT_FALSE(o.reply->reason().empty());

  idl::SimControl robot = Op(idl::OP_TELEPORT_ROBOT);
  robot.robot().team(idl::TEAM_YELLOW);
  robot.robot().id(7);
  robot.robot().on_field(true);
  o = t.client.Call(robot, kCall);
  EXPECT_EQ(o.code(), idl::CONTROL_UNKNOWN_ROBOT) << o.Describe();

  idl::SimControl speed = Op(idl::OP_SET_TIME_MODE);
  speed.time_mode(idl::TIME_SCALED);
  speed.speed(-1.0);
  o = t.client.Call(speed, kCall);
  EXPECT_EQ(o.code(), idl::CONTROL_OUT_OF_RANGE) << o.Describe();

  ASSERT_TRUE(t.client.Call(Op(idl::OP_PAUSE), kCall).ok());
  o = t.client.Call(Step(0), kCall);
  EXPECT_EQ(o.code(), idl::CONTROL_OUT_OF_RANGE) << o.Describe();
  // Paused, a STEP is fine; the refusals above changed nothing.
  o = t.client.Call(Step(5), kCall);
  EXPECT_TRUE(o.ok()) << o.Describe();
  EXPECT_EQ(o.code(), idl::CONTROL_OK);
  EXPECT_EQ(o.reply->error(), idl::CONTROL_OK);
}

TEST(ControlClient, CallbacksRunInDispatch) {
  const auto dds = UniqueDds("sim");
  SimUnderTest sim(test::OneRobot(), dds, TimeMode::kFreeRunning);
  ClientUnderTest t(dds, "async");
  ASSERT_TRUE(t.client.WaitForServer(Clock::now() + kCall));
  std::vector<dds::ControlOutcome> seen;
  t.client.Send(Op(idl::OP_PAUSE), kCall, [&](const dds::ControlOutcome& o) { seen.push_back(o); });
  t.client.Send(Step(3), kCall, [&](const dds::ControlOutcome& o) { seen.push_back(o); });
  const auto deadline = Clock::now() + kCall;
  while (seen.size() < 2 && Clock::now() < deadline) {
    t.client.Dispatch();
    if (seen.size() < 2) t.wakeup.WaitUntil(deadline);
  }
  ASSERT_EQ(seen.size(), 2u);
  EXPECT_EQ(seen[0].reply->op(), idl::OP_PAUSE);
  EXPECT_TRUE(seen[0].ok());
  EXPECT_EQ(seen[1].reply->op(), idl::OP_STEP);
  EXPECT_TRUE(seen[1].ok()) << seen[1].Describe();
  EXPECT_EQ(seen[1].reply->frame(), seen[0].reply->frame() + 3);
}

// The simulation-protocol bridge's port threads share one client.
TEST(ControlClient, ThreadsSharingAClientEachGetTheirOwnReplies) {
  const auto dds = UniqueDds("sim");
  SimUnderTest sim(test::OneRobot(), dds, TimeMode::kFreeRunning);
  ClientUnderTest t(dds, "shared");
  ASSERT_TRUE(t.client.WaitForServer(Clock::now() + kCall));
  constexpr int kEach = 20;
  std::atomic<int> mismatched{0};
  std::atomic<int> failed{0};
  auto run = [&](double y, idl::ControlOp op) {
    for (int i = 0; i < kEach; ++i) {
      // Thread 0 teleports the ball (OK); thread 1 asks for a bad speed (refused).
      idl::SimControl c = op == idl::OP_TELEPORT_BALL ? BallAt(0.01 * i, y) : Op(idl::OP_SET_TIME_MODE);
      c.time_mode(idl::TIME_SCALED);
      c.speed(-1.0);
      const dds::ControlOutcome o = t.client.Call(c, kCall);
      if (!o.reply) {
        ++failed;
      } else if (o.reply->request_id() != o.request_id || o.reply->op() != op ||
                 o.ok() != (op == idl::OP_TELEPORT_BALL)) {
        ++mismatched;
      }
    }
  };
  std::thread a(run, 0.5, idl::OP_TELEPORT_BALL);
  std::thread b(run, -0.5, idl::OP_SET_TIME_MODE);
  a.join();
  b.join();
  EXPECT_EQ(failed.load(), 0);
  EXPECT_EQ(mismatched.load(), 0);
  EXPECT_EQ(t.client.stray_replies(), 0u);
}

TEST(ControlClient, NoServerIsNamedAndNothingIsSent) {
  const auto dds = UniqueDds("lonely");
  ClientUnderTest t(dds, "lonely");
  const dds::ControlOutcome o = t.client.Call(Op(idl::OP_PAUSE), std::chrono::milliseconds(300));
  EXPECT_EQ(o.error, dds::ControlCallError::kNoServer) << o.Describe();
  EXPECT_FALSE(o.reply);
  std::optional<dds::ControlOutcome> async;
  t.client.Send(Op(idl::OP_PAUSE), kCall, [&](const dds::ControlOutcome& r) { async = r; });
  t.client.Dispatch();  // settled at once: no reader to send to
  ASSERT_TRUE(async);
  EXPECT_EQ(async->error, dds::ControlCallError::kNoServer);
  EXPECT_STREQ(dds::ControlCallErrorName(async->error), "no_server");
}

// More requests waiting than kMaxOutstanding: the oldest is given up, and its callback still hears so (a page
// whose request was forgotten waited for an answer for good).
TEST(ControlClient, ARequestGivenUpPastTheLimitStillGetsItsCallback) {
  const auto dds = UniqueDds("crowded");
  ClientUnderTest t(dds, "crowded");
  std::map<uint64_t, dds::ControlCallError> outcomes;
  std::vector<uint64_t> ids;
  for (size_t i = 0; i <= dds::ControlClient::kMaxOutstanding; ++i)
    ids.push_back(t.client.Send(Op(idl::OP_PAUSE), kCall,
                                [&](const dds::ControlOutcome& o) { outcomes[o.request_id] = o.error; }));
  EXPECT_EQ(t.client.Dispatch(), dds::ControlClient::kMaxOutstanding + 1);
  ASSERT_EQ(outcomes.size(), ids.size());
  EXPECT_EQ(outcomes.at(ids.front()), dds::ControlCallError::kNoServer);  // the outcome it had when given up
  EXPECT_EQ(outcomes.at(ids.back()), dds::ControlCallError::kNoServer);
}

// A server that reads requests and answers only what the test tells it to.
struct FakeServer {
  explicit FakeServer(const dds::ParticipantOptions& o)
      : participant(o),
        requests(participant.MakeReader<idl::SimControlPubSubType>(dds::Topic::kControl, [this] { wakeup.Notify(); })),
        replies(participant.MakeWriter<idl::SimControlReplyPubSubType>(dds::Topic::kControlReply)) {}
  std::optional<idl::SimControl> NextRequest(Clock::time_point deadline) {
    while (inbox.empty()) {
      std::vector<idl::SimControl> in;
      if (requests->Take(&in)) inbox.insert(inbox.end(), in.begin(), in.end());
      if (!inbox.empty()) break;
      if (Clock::now() >= deadline) return std::nullopt;
      wakeup.WaitUntil(deadline);
    }
    idl::SimControl r = inbox.front();
    inbox.erase(inbox.begin());
    return r;
  }
  Wakeup wakeup;
  dds::Participant participant;
  std::unique_ptr<dds::Reader<idl::SimControlPubSubType>> requests;
  std::unique_ptr<dds::Writer<idl::SimControlReplyPubSubType>> replies;
  std::vector<idl::SimControl> inbox;
};

TEST(ControlClient, SilenceIsATimeoutAndGarbageIsCountedAndDropped) {
  const auto dds = UniqueDds("fake");
  FakeServer server(dds);
  ClientUnderTest t(dds, "victim");
  ASSERT_TRUE(t.client.WaitForServer(Clock::now() + kCall));

  // No answer: a named timeout.
  const dds::ControlOutcome silent = t.client.Call(Op(idl::OP_PAUSE), std::chrono::milliseconds(300));
  EXPECT_EQ(silent.error, dds::ControlCallError::kTimeout) << silent.Describe();
  ASSERT_TRUE(server.NextRequest(Clock::now() + kCall));  // it was sent

  const uint64_t id = t.client.Send(Op(idl::OP_RESUME), kCall);
  const std::optional<idl::SimControl> request = server.NextRequest(Clock::now() + kCall);
  ASSERT_TRUE(request);
  EXPECT_EQ(request->client(), "victim");
  EXPECT_EQ(request->request_id(), id);
  idl::SimControlReply reply;
  reply.client("victim");
  reply.op(idl::OP_RESUME);
  // Garbage first: an id nobody asked for, an out-of-range result, a late reply
  // to the timed-out request, an OK that carries an error code, another client's.
  reply.request_id(id + 1000);
  server.replies->Write(reply);
  reply.request_id(id);
  reply.result(static_cast<idl::ControlResult>(7));
  server.replies->Write(reply);
  reply.result(idl::RESULT_OK);
  reply.error(idl::CONTROL_NOT_FINITE);
  server.replies->Write(reply);
  reply.error(idl::CONTROL_OK);
  reply.request_id(silent.request_id);
  server.replies->Write(reply);
  reply.client("someone-else");
  reply.request_id(id);
  server.replies->Write(reply);
  // Then the real answer.
  reply.client("victim");
  reply.request_id(id);
  reply.frame(42);
  server.replies->Write(reply);

  const dds::ControlOutcome o = t.client.Wait(id);
  ASSERT_TRUE(o.ok()) << o.Describe();
  EXPECT_EQ(o.reply->frame(), 42u);
  // One writer, reliable: everything before the answer was taken with or before it.
  EXPECT_EQ(t.client.stray_replies(), 2u);  // id + 1000, and the late one
  EXPECT_EQ(t.client.bad_replies(), 2u);    // result 7, OK with an error code
}

}  // namespace
}  // namespace turf::test
