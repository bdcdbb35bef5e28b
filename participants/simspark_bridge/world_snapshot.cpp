#include "participants/simspark_bridge/world_snapshot.h"

namespace turf {

std::vector<simspark::RobotMove> SimSparkWorld::ParkPoses(const LeggedLockstep& link) {
  std::vector<simspark::RobotMove> park;
  for (const idl::LinkState& links : link.state().links())
    park.push_back(TorsoMove<simspark::RobotMove>(links.robot(), links, false));
  return park;
}

simspark::WorldSnapshot SimSparkWorld::SnapshotOf(const idl::LeggedState& state) {
  simspark::WorldSnapshot w = WorldOf<simspark::WorldSnapshot>(state, [](const idl::LeggedState& s, size_t i) {
    simspark::RobotSnapshot r;
    r.name = s.joints()[i].robot();
    r.joint_names = s.joints()[i].name();
    r.joint_positions = s.joints()[i].position();
    r.gyro = ToArray(s.imu()[i].angular_velocity());
    r.accelerometer = ToArray(s.imu()[i].linear_acceleration());
    for (const idl::ForceReading& f : s.force()[i].sensors())
      r.feet.push_back({f.name(), f.contact(), ToArray(f.point()), ToArray(f.force())});
    r.links = LinkPoses<simspark::RobotSnapshot::Link>(s.links()[i]);
    r.velocity = ToEigen(s.imu()[i].base_velocity());
    return r;
  });
  w.ball_velocity = ToEigen(state.ball_velocity());
  for (const idl::BallTouch& t : state.ball_touches()) {
    for (simspark::RobotSnapshot& r : w.robots)
      if (r.name == t.robot()) r.ball_touch_time = static_cast<double>(t.sim_time_ns()) * 1e-9;
  }
  for (const idl::RobotContact& c : state.robot_contacts())
    w.robot_contacts.push_back({c.robot_a(), c.robot_b(), ToEigen(c.point())});
  return w;
}

idl::JointTarget SimSparkWorld::Target(const simspark::JointVelocity& v) {
  idl::JointTarget t;
  t.name(v.joint);
  t.mode(idl::JOINT_VELOCITY);
  t.value(v.velocity);
  t.kp(-1);
  t.kd(-1);
  return t;
}

}  // namespace turf
