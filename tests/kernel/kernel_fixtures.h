// Scenes and deterministic drivers for the kernel tests.
#pragma once

#include <cmath>
#include <stdexcept>
#include <string>

#include "kernel/legged_kernel.h"
#include "kernel/ssl_kernel.h"
#include "loader/legged_scene_yaml.h"
#include "loader/realism_yaml.h"
#include "loader/scene_yaml.h"

namespace turf::testing {

inline SensorRealism Preset(const std::string& name) {
  RealismLoadResult r = LoadRealism(name);
  if (!r.realism) throw std::runtime_error("no realism preset " + name);
  return *r.realism;
}

// The shipped division A match at the given realism.
inline Scene SslMatch(const std::string& realism = "realistic") {
  SceneLoadResult r = LoadSceneFile(TURF_SOURCE_DIR "/configs/scenes/ssl_div_a.yaml");
  if (!r.scene) throw std::runtime_error(r.errors.front());
  r.scene->realism = Preset(realism);
  return std::move(*r.scene);
}

// The shipped SimSpark match scene (Nao robots on the 3D field).
inline LeggedScene LeggedMatch(const std::string& realism = "realistic") {
  LeggedSceneLoadResult r = LoadLeggedSceneFile(TURF_SOURCE_DIR "/configs/scenes/simspark_3d.yaml");
  if (!r.scene) throw std::runtime_error(r.errors.front());
  r.scene->realism = Preset(realism);
  return std::move(*r.scene);
}

// The ball 5 cm in front of blue robot 0's face, which drives at it kicking.
inline void BallBeforeBlueZero(SslKernel& k) {
  const RobotSnapshot& r = k.state().robots[k.world().RobotIndex(Team::kBlue, 0)];
  const double d = k.scene().robot.center_to_dribbler + k.scene().ball.radius + 0.05;
  BallTeleport t;
  t.position = {r.x + d * std::cos(r.yaw), r.y + d * std::sin(r.yaw), k.scene().ball.radius};
  k.TeleportBall(t);
}

// Every robot of both teams driven by a function of the frame: turning,
// driving and kicking now and then, so radio, kicks and feedback all happen.
inline void DriveSsl(SslKernel& k) {
  const uint64_t f = k.frame();
  for (const RobotSetup& setup : k.scene().robots) {
    if (!setup.on_field) continue;
    RobotCommand c;
    c.team = setup.team;
    c.id = setup.id;
    c.move = MoveKind::kLocalVelocity;
    c.velocity = {std::sin(0.01 * f + setup.id), 0.5 * std::cos(0.013 * f), 0.8 * std::sin(0.007 * f)};
    if (setup.team == Team::kBlue && setup.id == 0) c.velocity = {0.3, 0.0, 0.0};  // towards the ball (test)
    if ((f + setup.id) % 97 == 0 || (setup.team == Team::kBlue && setup.id == 0 && f % 10 == 0)) {
      c.kick = KickKind::kFlat;
      c.kick_speed = 3.0;
    }
    k.Command(setup.team, c);
  }
}

// Every joint of every robot swinging slowly (velocity mode).
inline void DriveLegged(LeggedKernel& k) {
  const double t = k.time_ns() * 1e-9;
  LeggedWorldState s;
  k.world().State(&s);
  for (size_t r = 0; r < s.robots.size(); ++r) {
    std::vector<JointCommand> commands;
    for (size_t j = 0; j < s.robots[r].joint_names.size(); ++j)
      commands.push_back({s.robots[r].joint_names[j], JointMode::kVelocity, 0.3 * std::sin(2.0 * t + 0.1 * j)});
    k.SetJointCommands(static_cast<int>(r), commands);
  }
}

}  // namespace turf::testing
