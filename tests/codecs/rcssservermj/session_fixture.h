// A fake world for the RCSSServerMJ session's tests (no physics) and a fixture with a session over it.
#pragma once

#include <map>
#include <string>
#include <utility>
#include <vector>

#include "codecs/rcssservermj/session.h"

namespace turf::rcssservermj {

// A world of parked robots that only moves where the session asks (no physics).
class FakeWorld {
 public:
  explicit FakeWorld(const std::vector<SceneRobot>& robots) {
    for (const SceneRobot& r : robots) {
      MjRobotSnapshot s;
      s.name = r.name;
      for (const MjJoint& j : FindModel(r.model)->joints) s.joint_names.push_back(j.joint);
      s.positions.assign(s.joint_names.size(), 0.0);
      s.velocities.assign(s.joint_names.size(), 0.0);
      s.acc = {0, 0, 9.81};
      const MjRobotModel& m = *FindModel(r.model);
      for (const char* body : {"torso", m.camera.body, m.lfoot.body, m.rfoot.body}) s.links.push_back({body, {}, {}});
      world_.robots.push_back(s);
      Place(r.park);
    }
  }
  void Place(const RobotMove& move) {
    for (MjRobotSnapshot& r : world_.robots) {
      if (r.name != move.robot) continue;
      for (MjLink& l : r.links) {
        l.orientation = move.orientation;
        l.position = move.position + move.orientation * Offset(l.name);
      }
    }
  }
  static Eigen::Vector3d Offset(const std::string& body) {
    if (body == "H2" || body == "Head_2") return {0.06, 0, 0.3};
    if (body == "left_foot_link") return {0, 0.1, -0.6};
    if (body == "right_foot_link") return {0, -0.1, -0.6};
    return Eigen::Vector3d::Zero();
  }
  // One cycle: the session's requests, then the world after the step.
  WorldRequests Cycle(Session* s) {
    WorldRequests r = s->TakeRequests();
    for (const RobotMove& m : r.moves) Place(m);
    if (r.ball) world_.ball = *r.ball;
    world_.time += kCycleSeconds;
    s->Advance(world_);
    return r;
  }
  MjWorldSnapshot world_;
};

inline std::vector<SceneRobot> Robots(int t1, int k1) {
  std::vector<SceneRobot> out;
  for (int i = 0; i < t1 + k1; ++i) {
    const bool is_t1 = i < t1;
    RobotMove park{std::string(is_t1 ? "t1_" : "k1_") + std::to_string(i + 1), {i * 1.0, -40, 0.7}, {}, false};
    out.push_back({park.robot, is_t1 ? "T1" : "K1", park});
  }
  return out;
}

// The sequential loop: no latency, an action acts in the next cycle.
inline SessionOptions Sequential() {
  SessionOptions o;
  o.sequential = true;
  return o;
}

struct Fixture {
  explicit Fixture(SessionOptions o = {}, int t1 = 24, int k1 = 1)
      : robots(Robots(t1, k1)), session(o, robots), world(robots) {}
  int Join(const std::string& init) {
    const int id = session.Connect();
    session.Receive(id, init);
    return id;
  }
  // An agent joined and activated (one cycle), with its init message.
  int JoinAndCycle(const std::string& init) {
    const int id = Join(init);
    world.Cycle(&session);
    return id;
  }
  // Two agents joined and activated (one cycle), with their init messages.
  std::pair<int, int> JoinTwo(const std::string& init_a, const std::string& init_b) {
    const std::pair<int, int> ids{Join(init_a), Join(init_b)};
    world.Cycle(&session);
    return ids;
  }
  std::map<int, std::string> Outputs() {
    std::map<int, std::string> out;
    for (auto& [id, text] : session.TakeOutputs()) out[id] = text;
    return out;
  }
  std::vector<SceneRobot> robots;
  Session session;
  FakeWorld world;
};

}  // namespace turf::rcssservermj
