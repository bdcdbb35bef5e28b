// libFuzzer: arbitrary bytes restored as an RCSSServerMJ league snapshot (Session::RestoreLeague) and as a
// referee (Referee::Restore). A restore must refuse what it cannot use without crashing and, when it refuses,
// change nothing; a session that accepted a snapshot must run on.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

#include "codecs/rcssservermj/session.h"
#include "tests/support/league_snapshot.h"

namespace {

namespace mj = turf::rcssservermj;

std::vector<mj::SceneRobot> Robots() {
  std::vector<mj::SceneRobot> robots;
  for (const char* model : {"T1", "K1", "T1"}) {
    const std::string name = "r" + std::to_string(robots.size() + 1);
    robots.push_back({name, model, {name, Eigen::Vector3d(static_cast<double>(robots.size()), -12, 0.7), {}, false}});
  }
  return robots;
}

// Each robot's torso and head where its park put it; the ball at the centre.
mj::MjWorldSnapshot World(double time) {
  mj::MjWorldSnapshot w;
  w.time = time;
  w.ball = Eigen::Vector3d(0, 0, 0.11);
  for (const mj::SceneRobot& robot : Robots()) {
    const mj::MjRobotModel& model = *mj::FindModel(robot.model);
    mj::MjRobotSnapshot r;
    r.name = robot.name;
    for (const mj::MjJoint& j : model.joints) r.joint_names.push_back(j.joint);
    r.positions.assign(r.joint_names.size(), 0.1);
    r.velocities.assign(r.joint_names.size(), -0.2);
    for (const char* body : {"torso", model.camera.body, model.lfoot.body, model.rfoot.body})
      r.links.push_back({body, robot.park.position, Eigen::Quaterniond::Identity()});
    w.robots.push_back(r);
  }
  return w;
}

struct Match {
  Match() : session({}, Robots()) {
    const int a = session.Connect();
    const int b = session.Connect();
    const int c = session.Connect();
    session.Receive(a, "(init T1 Alpha 1)");
    session.Receive(b, "(init K1 Alpha 2)");
    session.Receive(c, "(init T1 Beta 1)");
    for (int i = 0; i < 4; ++i) Cycle();
    session.Receive(a, "(lle4 30 0 50 1 0)(beam -1 1 0)");
    session.Monitor("(kickOff)");
    Cycle();
    session.Receive(c, "(he1 10 0 5 1 0)");
    start = session.SaveLeague();
  }
  void Cycle() { turf::test::FuzzCycle(session, World); }
  mj::Session session;
  std::string start;
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return turf::test::FuzzLeague<Match>(data, size, World, [](turf::StateReader& in) {
    mj::Referee referee(*mj::FindRuleBook("fifa"), *mj::FindField("fifa"), 0.11);
    referee.Restore(in);
    if (in.ok()) referee.Update(0.02, Eigen::Vector3d(0, 0, 0.11), std::nullopt);
  });
}
