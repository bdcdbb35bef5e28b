// libFuzzer: arbitrary bytes restored as a SimSpark league snapshot
// (Session::RestoreLeague) and as a game (Game::Restore). A restore must
// refuse what it cannot use without crashing and, when it refuses, change
// nothing; a session that accepted a snapshot must run on.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

#include "codecs/simspark/session.h"
#include "tests/support/league_snapshot.h"

namespace {

namespace ss = turf::simspark;

// Two robots standing apart, each with a torso and a head.
ss::WorldSnapshot World(double time) {
  ss::WorldSnapshot w;
  w.time = time;
  w.ball = Eigen::Vector3d(0, 0, 0.042);
  for (int i = 0; i < 2; ++i) {
    ss::RobotSnapshot r;
    r.name = "nao_" + std::to_string(i + 1);
    r.joint_names = {"hj1", "hj2"};
    r.joint_positions = {0.1, -0.2};
    const Eigen::Vector3d at(-3.0 + 6.0 * i, 1.0, 0.4);
    r.links.push_back({"torso", at, Eigen::Quaterniond::Identity()});
    r.links.push_back({"head", at + Eigen::Vector3d(0, 0, 0.2), Eigen::Quaterniond::Identity()});
    w.robots.push_back(r);
  }
  return w;
}

struct Match {
  Match() : session({}, {"nao_1", "nao_2"}, {}) {
    const int a = session.Connect();
    const int b = session.Connect();
    session.Receive(a, "(scene rsg/agent/nao/nao_hetero.rsg 0)(init (unum 1)(teamname Alpha))");
    session.Receive(b, "(scene rsg/agent/nao/nao_hetero.rsg 1)(init (unum 1)(teamname Beta))");
    for (int i = 0; i < 4; ++i) Cycle();
    session.Receive(a, "(say hi)(he1 0.5)");
    session.Trainer("(kickOff Left)", ss::TrainerRole::kOperator);
    start = session.SaveLeague();
  }
  void Cycle() { turf::test::FuzzCycle(session, World); }
  ss::Session session;
  std::string start;
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return turf::test::FuzzLeague<Match>(data, size, World, [](turf::StateReader& in) {
    ss::Game game;
    game.Restore(in);
    if (in.ok()) game.Update(0.02, Eigen::Vector3d(0, 0, 0.042), {ss::Toucher{ss::Side::kLeft, 1}});
  });
}
