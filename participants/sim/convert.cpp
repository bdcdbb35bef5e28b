#include "participants/sim/convert.h"

#include <cmath>
#include <utility>

#include "idl/values.h"
#include "participants/sim/enum_table.h"

namespace turf {

namespace {

using idl::V2;

idl::Vec3 V3(const Vec3& v) {
  idl::Vec3 out;
  out.x(v.x);
  out.y(v.y);
  out.z(v.z);
  return out;
}

Vec3 FromV3(const idl::Vec3& v) { return {v.x(), v.y(), v.z()}; }

// In place: the generated types' constructors, assignments and destructors are calls of their own (a world state at
// 100 Hz has ~100 of these vectors).
void SetV3(double x, double y, double z, idl::Vec3* out) {
  out->x(x);
  out->y(y);
  out->z(z);
}
void SetV3(const Vec3& v, idl::Vec3* out) { SetV3(v.x, v.y, v.z, out); }

constexpr std::pair<idl::MoveKind, MoveKind> kMoveKinds[] = {{idl::MOVE_NONE, MoveKind::kNone},
                                                             {idl::MOVE_LOCAL_VELOCITY, MoveKind::kLocalVelocity},
                                                             {idl::MOVE_GLOBAL_VELOCITY, MoveKind::kGlobalVelocity},
                                                             {idl::MOVE_WHEEL_VELOCITY, MoveKind::kWheelVelocity}};
constexpr std::pair<idl::KickKind, KickKind> kKickKinds[] = {
    {idl::KICK_NONE, KickKind::kNone}, {idl::KICK_FLAT, KickKind::kFlat}, {idl::KICK_CHIP, KickKind::kChip}};

idl::KickKind ToIdl(KickKind kind) { return ToIdlEnum(kKickKinds, kind, idl::KICK_NONE); }

}  // namespace

idl::Team ToIdl(Team team) { return team == Team::kBlue ? idl::TEAM_BLUE : idl::TEAM_YELLOW; }

bool FromIdl(idl::Team in, Team* out) {
  if (in == idl::TEAM_BLUE) {
    *out = Team::kBlue;
  } else if (in == idl::TEAM_YELLOW) {
    *out = Team::kYellow;
  } else {
    return false;
  }
  return true;
}

void ToIdl(const WorldSnapshot& s, idl::WorldState* out) {
  out->sim_time_ns(s.time_ns);
  out->frame(s.frame);
  SetV3(s.ball.position, &out->ball().position());
  SetV3(s.ball.velocity, &out->ball().velocity());
  SetV3(s.ball.angular_velocity, &out->ball().angular_velocity());
  out->robots().resize(s.robots.size());
  for (size_t i = 0; i < s.robots.size(); ++i) {
    const RobotSnapshot& r = s.robots[i];
    idl::RobotState& o = out->robots()[i];
    o.team(ToIdl(r.team));
    o.id(static_cast<uint8_t>(r.id));
    o.on_field(r.on_field);
    SetV3(r.x, r.y, 0.0, &o.position());
    idl::Quat& q = o.orientation();
    q.w(std::cos(r.yaw / 2));
    q.x(0.0);
    q.y(0.0);
    q.z(std::sin(r.yaw / 2));
    o.yaw(r.yaw);
    SetV3(r.vx, r.vy, 0.0, &o.linear_velocity());
    SetV3(0.0, 0.0, r.omega, &o.angular_velocity());
  }
}

void ToIdl(const CameraFrame& f, idl::CameraFrame* out) {
  out->camera_id(static_cast<uint32_t>(f.camera_id));
  out->frame_number(f.frame_number);
  out->capture_time_ns(f.capture_time_ns);
  out->sent_time_ns(f.sent_time_ns);
  out->balls().resize(f.balls.size());
  for (size_t i = 0; i < f.balls.size(); ++i) {
    SetV3(f.balls[i].position, &out->balls()[i].position());
    out->balls()[i].confidence(f.balls[i].confidence);
  }
  out->robots().resize(f.robots.size());
  for (size_t i = 0; i < f.robots.size(); ++i) {
    const DetectedRobot& r = f.robots[i];
    idl::DetectedRobot& o = out->robots()[i];
    o.team(ToIdl(r.team));
    o.id(static_cast<uint8_t>(r.id));
    o.position().x(r.x);  // in place, as SetV3
    o.position().y(r.y);
    o.orientation(r.orientation);
    o.height(r.height);
    o.confidence(r.confidence);
  }
}

idl::SslField FieldToIdl(const Scene& scene, const std::vector<CameraSpec>& cameras) {
  const FieldParams& f = scene.field;
  const BallParams& b = scene.ball;
  idl::SslField out;
  out.division(static_cast<uint8_t>(f.division));
  out.field_length(f.length);
  out.field_width(f.width);
  out.boundary_width(f.boundary_width);
  out.boundary_width_goal_line(f.boundary_width_goal_line);
  out.goal_width(f.goal_width);
  out.goal_depth(f.goal_depth);
  out.goal_height(f.goal_height);
  out.goal_wall_thickness(f.goal_wall_thickness);
  out.penalty_area_depth(f.penalty_area_depth);
  out.penalty_area_width(f.penalty_area_width);
  out.center_circle_radius(f.center_circle_radius);
  out.line_thickness(f.line_thickness);
  out.goal_center_to_penalty_mark(f.goal_center_to_penalty_mark);
  out.ball_radius(b.radius);
  out.max_robot_radius(scene.robot.radius);
  out.ball_acc_slide(b.acc_slide);
  out.ball_acc_roll(b.acc_roll);
  out.ball_k_switch(b.k_switch);
  out.chip_damping_xy_first_hop(b.chip_damping_xy_first_hop);
  out.chip_damping_xy_other_hops(b.chip_damping_xy_other_hops);
  out.chip_damping_z(b.floor_restitution);
  out.camera_rate_hz(scene.cameras.rate_hz);
  const RobotParams& r = scene.robot;
  out.robots_per_team(static_cast<uint8_t>(scene.robots_per_team));
  out.robot_height(r.height);
  out.center_to_dribbler(r.center_to_dribbler);
  out.wheel_radius(r.drive.wheel_radius);
  out.wheel_angles(r.drive.wheel_angles);
  out.max_flat_kick_speed(r.kicker.max_flat_speed);
  out.max_chip_kick_speed(r.kicker.max_chip_speed);
  out.default_chip_angle(r.kicker.default_chip_angle);
  for (const CameraSpec& c : cameras) {
    idl::CameraInfo info;
    info.id(static_cast<uint32_t>(c.id));
    info.position(V3(c.position));
    info.area_min(V2(c.min_x, c.min_y));
    info.area_max(V2(c.max_x, c.max_y));
    info.focal_length(scene.cameras.focal_length);
    info.image_width(static_cast<uint32_t>(scene.cameras.image_width));
    info.image_height(static_cast<uint32_t>(scene.cameras.image_height));
    out.cameras().push_back(info);
  }
  return out;
}

idl::SslRobotFeedback FeedbackToIdl(const RobotSnapshot& r, int64_t time_ns) {
  idl::SslRobotFeedback out;
  out.team(ToIdl(r.team));
  out.id(static_cast<uint8_t>(r.id));
  out.sim_time_ns(time_ns);
  out.ball_contact(r.ball_contact);
  out.kick_count(r.kick_count);
  out.last_kick(ToIdl(r.last_kick));
  return out;
}

InputError FromIdl(const idl::SslRobotCommand& in, RobotCommand* out) {
  if (!FromIdl(in.team(), &out->team)) return InputError::kOutOfRange;
  out->id = in.id();
  if (!FromIdlEnum(kMoveKinds, in.move(), &out->move)) return InputError::kOutOfRange;
  if (!FromIdlEnum(kKickKinds, in.kick(), &out->kick)) return InputError::kOutOfRange;
  out->velocity = FromV3(in.velocity());
  out->wheel_velocity = in.wheel_velocity();
  out->kick_speed = in.kick_speed();
  out->chip_angle = in.chip_angle();
  out->dribbler_speed = in.dribbler_speed();
  return InputError::kOk;
}

InputError FromIdl(const idl::BallTeleport& in, BallTeleport* out) {
  out->position = FromV3(in.position());
  out->velocity = FromV3(in.velocity());
  out->roll = in.roll();
  return InputError::kOk;
}

InputError FromIdl(const idl::RobotTeleport& in, RobotTeleport* out) {
  if (!FromIdl(in.team(), &out->team)) return InputError::kOutOfRange;
  out->id = in.id();
  out->on_field = in.on_field();
  out->x = in.position().x();
  out->y = in.position().y();
  out->orientation = in.orientation();
  out->velocity = FromV3(in.velocity());
  return InputError::kOk;
}

}  // namespace turf
