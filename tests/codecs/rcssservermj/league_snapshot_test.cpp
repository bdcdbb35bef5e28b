// The RCSSServerMJ league's snapshot (Session::SaveLeague / RestoreLeague): a restored match sends the same bytes
// and asks the world for the same things, with inputs pending or not, in the parallel loop and in sync mode; a
// snapshot the connected players do not fit, a truncated or corrupted one is refused and changes nothing.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <string>
#include <utility>

#include "codecs/rcssservermj/session.h"
#include "tests/codecs/rcssservermj/session_fixture.h"
#include "tests/support/league_snapshot.h"

namespace turf::rcssservermj {
namespace {

bool Contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// Everything the world is asked for, as text (moves, ball, every joint command), so runs compare byte for byte.
std::string Describe(const WorldRequests& r) {
  std::string out;
  for (const RobotMove& m : r.moves)
    out += fmt::format("move {} {} {} {} {}\n", m.robot, m.position.x(), m.position.y(), m.position.z(),
                       m.orientation.w());
  if (r.ball) out += fmt::format("ball {} {}\n", r.ball->x(), r.ball->y());
  for (const auto& [robot, commands] : r.joints)
    for (const PdCommand& c : commands)
      out += fmt::format("{} {} {} {} {} {} {}\n", robot, c.joint, c.q, c.dq, c.kp, c.kd, c.tau);
  return out;
}

// A scripted match of four players (three T1, one K1; a T1 spare): beams, a coin-toss kick-off, motor commands every
// cycle, the ball placed off its spot (PlayOn), out over a touch line (a kick-in), back to BeforeKickOff with beams and
// coin tosses. Inputs(i) gives cycle i's inputs, the same on every run; Step(i) also runs the cycle and
// returns every byte the session sent, by player, and what it asked of the world.
struct LeagueMatch : test::LeagueScript<LeagueMatch> {
  explicit LeagueMatch(SessionOptions o = Options()) : f(o, 4, 1) {
    a = f.Join("(init T1 Alpha 1)");
    b = f.Join("(init K1 Alpha 2)");
    c = f.Join("(init T1 Beta 1)");
    d = f.Join("(init T1 Beta 2)");
  }
  static SessionOptions Options() {
    SessionOptions o;
    o.seed = 11;
    return o;
  }

  void Inputs(int i) {
    if (i == 2 || i == 22) {
      f.session.Receive(a, "(beam -1 0.5 0)");
      f.session.Receive(c, "(beam -3 2 45)");
    }
    if (i == 3 || (i >= 24 && i <= 28)) f.session.Monitor("(kickOff)");  // five tosses after a restore at 10
    if (i == 8) f.session.Monitor("(ball (pos 0.5 0.2 0.11))");
    if (i == 14) f.session.Monitor("(ball (pos 3 40 0.11))");
    if (i == 20) f.session.Monitor("(playMode BeforeKickOff)");
    if (i == 0) return;  // nobody active yet
    f.session.Receive(a, fmt::format("(lle4 {} 0 40 1 0)", 2 * i));
    f.session.Receive(b, fmt::format("(he1 {} 5 10 0.5 0.1)", -i));
    if (i % 2 == 1) f.session.Receive(c, fmt::format("(rle4 {} 0 30 1 0)(syn)", i));
    f.session.Receive(d, "(syn)");
  }
  std::string Cycle() {
    std::string log = Describe(f.world.Cycle(&f.session));
    for (const auto& [id, text] : f.Outputs()) log += Name(id) + ":" + text + "\n";
    return log;
  }
  Session& session() { return f.session; }
  FakeWorld& world() { return f.world; }
  std::string Name(int id) const { return test::NameOf(id, {{a, "a"}, {b, "b"}, {c, "c"}, {d, "d"}}); }

  Fixture f;
  int a = 0, b = 0, c = 0, d = 0;
};

TEST(MjLeagueSnapshot, RestoredMatchSendsTheSameBytes) {
  LeagueMatch m;
  EXPECT_EQ(m.RestoredMatchSendsTheSameBytes(
                10, 30,
                {"(See", "(pol ", "(pm PlayOn)", "(pm KickIn_", "(pm KickOff_", "(pm BeforeKickOff)", "(sl 0)",
                 "ball 3 3", "move t1_1", "t1_1 Left_Knee_Pitch"}),
            "");
}

// Saved between a cycle's inputs and its step: agents' messages and monitor commands not yet taken are in it.
TEST(MjLeagueSnapshot, SavedWithInputsPendingGoesOnTheSame) {
  LeagueMatch m;
  EXPECT_EQ(m.SavedWithInputsPendingGoesOnTheSame(22, 30, [&] { m.f.session.Monitor("(ball (pos -1 1 0.11))"); }), "");
}

// Sync mode: the counts of perceptions sent and answered decide when the world may step.
TEST(MjLeagueSnapshot, SyncModeWaitsForTheSameAnswersAfterARestore) {
  SessionOptions o = LeagueMatch::Options();
  o.sync_mode = true;
  LeagueMatch m(o);
  const std::string snapshot = m.SaveAfter(12);
  ASSERT_FALSE(m.f.session.Waiting().empty());  // every player owes the answer to its last perception
  const std::vector<int> waiting = m.f.session.Waiting();
  const FakeWorld world = m.f.world;
  const std::string first = m.Run(12, 20);
  m.f.world = world;
  ASSERT_EQ(m.f.session.RestoreLeague(snapshot), "");
  EXPECT_EQ(m.f.session.Waiting(), waiting);
  EXPECT_EQ(m.Run(12, 20), first);
}

TEST(MjLeagueSnapshot, SnapshotOfTheSameStateIsTheSameBytes) {
  LeagueMatch m;
  EXPECT_EQ(m.SnapshotOfTheSameStateIsTheSameBytes(12), "");
}

// A player that left and came back (another connection) takes the snapshot's player state.
TEST(MjLeagueSnapshot, ReconnectedPlayerTakesTheSavedState) {
  LeagueMatch m;
  const std::string snapshot = m.SaveAfter(10);
  m.Run(10, 16);
  m.f.session.Disconnect(m.d);
  m.d = m.f.Join("(init T1 Beta 2)");
  m.f.world.Cycle(&m.f.session);
  ASSERT_EQ(m.f.session.RestoreLeague(snapshot), "");
  EXPECT_EQ(m.f.session.SaveLeague(), snapshot);
}

TEST(MjLeagueSnapshot, PlayersThatDoNotFitAreRefused) {
  LeagueMatch m;
  const std::string snapshot = m.SaveAfter(10);
  m.f.session.Disconnect(m.d);
  m.f.world.Cycle(&m.f.session);
  const std::string before = m.f.session.SaveLeague();
  EXPECT_TRUE(Contains(m.f.session.RestoreLeague(snapshot), "not connected")) << "player right 2 is gone";
  EXPECT_EQ(m.f.session.SaveLeague(), before);

  LeagueMatch extra;
  const std::string four = extra.SaveAfter(10);
  extra.f.Join("(init T1 Beta 3)");
  extra.f.world.Cycle(&extra.f.session);
  const std::string why = extra.f.session.RestoreLeague(four);
  EXPECT_TRUE(Contains(why, "not in the snapshot")) << why;
}

TEST(MjLeagueSnapshot, TruncatedOrCorruptedIsRefusedAndChangesNothing) {
  LeagueMatch m;
  const std::string snapshot = m.SaveAfter(8);
  m.Run(8, 12);
  const std::string now = m.f.session.SaveLeague();
  EXPECT_EQ(test::DamagedSnapshotsChangeNothing(
                snapshot, now, [&] { return m.f.session.SaveLeague(); },
                [&](const std::string& bytes) { return m.f.session.RestoreLeague(bytes); }, 7),
            "");
  EXPECT_EQ(m.f.session.RestoreLeague(snapshot + "x"), "invalid league snapshot: trailing bytes");
  EXPECT_EQ(m.f.session.RestoreLeague(std::string("TSLG") + snapshot.substr(4)), "not an RCSSServerMJ league snapshot");
}

}  // namespace
}  // namespace turf::rcssservermj
