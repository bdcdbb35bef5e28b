#include "core/state_fields.h"

namespace turf {

namespace {

constexpr auto kTeamEnd = static_cast<Team>(kTeamCount);
constexpr auto kKickEnd = static_cast<KickKind>(3);
constexpr auto kMoveEnd = static_cast<MoveKind>(4);
constexpr size_t kMaxDetections = 1024;  // per camera frame

void SaveVec3(const Vec3& v, StateWriter& out) {
  out.Put(v.x);
  out.Put(v.y);
  out.Put(v.z);
}

Vec3 RestoreVec3(StateReader& in) {
  Vec3 v;
  v.x = in.Get<double>();
  v.y = in.Get<double>();
  v.z = in.Get<double>();
  return v;
}

}  // namespace

void SaveCommand(const RobotCommand& c, StateWriter& out) {
  out.Put(c.team);
  out.Put(c.id);
  out.Put(c.move);
  SaveVec3(c.velocity, out);
  for (double w : c.wheel_velocity) out.Put(w);
  out.Put(c.kick);
  out.Put(c.kick_speed);
  out.Put(c.chip_angle);
  out.Put(c.dribbler_speed);
}

RobotCommand RestoreCommand(StateReader& in) {
  RobotCommand c;
  c.team = in.Enum(kTeamEnd);
  c.id = in.Get<int>();
  c.move = in.Enum(kMoveEnd);
  c.velocity = RestoreVec3(in);
  for (double& w : c.wheel_velocity) w = in.Get<double>();
  c.kick = in.Enum(kKickEnd);
  c.kick_speed = in.Get<double>();
  c.chip_angle = in.Get<double>();
  c.dribbler_speed = in.Get<double>();
  return c;
}

void SaveArmedKick(const ArmedKick& k, StateWriter& out) {
  out.Put(k.kind);
  out.Put(k.speed);
  out.Put(k.chip_angle);
  out.Put(k.until_ns);
}

ArmedKick RestoreArmedKick(StateReader& in) {
  ArmedKick k;
  k.kind = in.Enum(kKickEnd);
  k.speed = in.Get<double>();
  k.chip_angle = in.Get<double>();
  k.until_ns = in.Get<int64_t>();
  return k;
}

void SaveCameraFrame(const CameraFrame& f, StateWriter& out) {
  out.Put(f.camera_id);
  out.Put(f.frame_number);
  out.Put(f.capture_time_ns);
  out.Put(f.sent_time_ns);
  out.Put<uint64_t>(f.balls.size());
  for (const DetectedBall& b : f.balls) {
    SaveVec3(b.position, out);
    out.Put(b.confidence);
  }
  out.Put<uint64_t>(f.robots.size());
  for (const DetectedRobot& r : f.robots) {
    out.Put(r.team);
    out.Put(r.id);
    out.Put(r.x);
    out.Put(r.y);
    out.Put(r.orientation);
    out.Put(r.height);
    out.Put(r.confidence);
  }
}

CameraFrame RestoreCameraFrame(StateReader& in) {
  CameraFrame f;
  f.camera_id = in.Get<int>();
  f.frame_number = in.Get<uint64_t>();
  f.capture_time_ns = in.Get<int64_t>();
  f.sent_time_ns = in.Get<int64_t>();
  f.balls.resize(in.Count(kMaxDetections));
  for (DetectedBall& b : f.balls) {
    b.position = RestoreVec3(in);
    b.confidence = in.Get<float>();
  }
  f.robots.resize(in.Count(kMaxDetections));
  for (DetectedRobot& r : f.robots) {
    r.team = in.Enum(kTeamEnd);
    r.id = in.Get<int>();
    r.x = in.Get<double>();
    r.y = in.Get<double>();
    r.orientation = in.Get<double>();
    r.height = in.Get<double>();
    r.confidence = in.Get<float>();
  }
  return f;
}

void SaveRealism(const SensorRealism& r, StateWriter& out) {
  const CameraRealism& c = r.camera;
  for (double v : {c.robot_position_stddev, c.robot_orientation_stddev, c.ball_position_stddev, c.robot_vanish,
                   c.ball_vanish, c.confidence_spread, c.processing_delay})
    out.Put(v);
  out.Put(c.ball_occlusion);
  SaveLinkParams(c.link, out);
  SaveLinkParams(r.command, out);
  out.Put(r.encoder.resolution);
  out.Put(r.encoder.noise_stddev);
  SaveLinkParams(r.encoder.link, out);
  for (double v : {r.imu.gyro_bias, r.imu.gyro_noise_stddev, r.imu.accel_bias, r.imu.accel_noise_stddev}) out.Put(v);
  SaveLinkParams(r.imu.link, out);
  SaveLinkParams(r.touch.link, out);
}

SensorRealism RestoreRealism(StateReader& in) {
  SensorRealism r;
  CameraRealism& c = r.camera;
  for (double* v : {&c.robot_position_stddev, &c.robot_orientation_stddev, &c.ball_position_stddev, &c.robot_vanish,
                    &c.ball_vanish, &c.confidence_spread, &c.processing_delay})
    *v = in.Get<double>();
  c.ball_occlusion = in.Bool();
  c.link = RestoreLinkParams(in);
  r.command = RestoreLinkParams(in);
  r.encoder.resolution = in.Get<double>();
  r.encoder.noise_stddev = in.Get<double>();
  r.encoder.link = RestoreLinkParams(in);
  for (double* v : {&r.imu.gyro_bias, &r.imu.gyro_noise_stddev, &r.imu.accel_bias, &r.imu.accel_noise_stddev})
    *v = in.Get<double>();
  r.imu.link = RestoreLinkParams(in);
  r.touch.link = RestoreLinkParams(in);
  if (in.ok() && CheckRealism(r)[0] != '\0') in.Fail("invalid sensor realism");
  return r;
}

}  // namespace turf
