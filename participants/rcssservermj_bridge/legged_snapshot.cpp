#include "participants/rcssservermj_bridge/legged_snapshot.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace turf {

std::string ModelOfLabel(const std::string& label) {
  std::string stem = std::filesystem::path(label).stem().string();
  std::transform(stem.begin(), stem.end(), stem.begin(), [](unsigned char c) { return std::toupper(c); });
  return stem;
}

std::vector<rcssservermj::SceneRobot> RcssServerMjWorld::SceneRobots(const LeggedLockstep& link) {
  const auto& robots = link.scene_info().robots();
  std::vector<rcssservermj::SceneRobot> scene;
  for (size_t i = 0; i < robots.size(); ++i) {
    const std::string& name = robots[i].robot();
    auto park = TorsoMove<rcssservermj::RobotMove>(name, link.state().links()[i], true);
    scene.push_back({name, ModelOfLabel(robots[i].model()), park});
  }
  return scene;
}

rcssservermj::MjWorldSnapshot RcssServerMjWorld::SnapshotOf(const idl::LeggedState& state) {
  return WorldOf<rcssservermj::MjWorldSnapshot>(state, [](const idl::LeggedState& s, size_t i) {
    rcssservermj::MjRobotSnapshot r;
    r.name = s.joints()[i].robot();
    r.joint_names = s.joints()[i].name();
    r.positions = s.joints()[i].position();
    r.velocities = s.joints()[i].velocity();
    r.gyro = ToArray(s.imu()[i].angular_velocity());
    r.acc = ToArray(s.imu()[i].linear_acceleration());
    r.links = LinkPoses<rcssservermj::MjLink>(s.links()[i]);
    return r;
  });
}

}  // namespace turf
