// Snapshot fields of core's plain structs (state_io.h): each struct's fields
// listed once, for saving and restoring. A restore fails on a value no save
// writes (an enum past its last value, invalid realism, too many detections).
#pragma once

#include "core/ball_handling.h"
#include "core/input_limits.h"
#include "core/scene.h"
#include "core/sensor_realism.h"
#include "core/ssl_cameras.h"
#include "core/state_io.h"
#include "core/types.h"

namespace turf {

inline constexpr size_t kMaxSnapshotDetections = 1024;  // per camera frame and kind
inline constexpr auto kTeamEnd = static_cast<Team>(kTeamCount);
inline constexpr auto kKickEnd = static_cast<KickKind>(3);
inline constexpr auto kMoveEnd = static_cast<MoveKind>(4);

template <class Io>
void Fields(Io& io, IoRef<Io, Vec3> v) {
  io(v.x, v.y, v.z);
}

template <class Io>
void Fields(Io& io, IoRef<Io, RobotCommand> c) {
  io(InRange(c.team, kTeamEnd), c.id, InRange(c.move, kMoveEnd), c.velocity, c.wheel_velocity,
     InRange(c.kick, kKickEnd), c.kick_speed, c.chip_angle, c.dribbler_speed);
  io.Check(CheckCommand(c) == InputError::kOk, "invalid command");
}

template <class Io>
void Fields(Io& io, IoRef<Io, ArmedKick> k) {
  io(InRange(k.kind, kKickEnd), k.speed, k.chip_angle, k.until_ns);
}

template <class Io>
void Fields(Io& io, IoRef<Io, DetectedBall> b) {
  io(b.position, b.confidence);
}

template <class Io>
void Fields(Io& io, IoRef<Io, DetectedRobot> r) {
  io(InRange(r.team, kTeamEnd), r.id, r.x, r.y, r.orientation, r.height, r.confidence);
}

template <class Io>
void Fields(Io& io, IoRef<Io, CameraFrame> f) {
  io(f.camera_id, f.frame_number, f.capture_time_ns, f.sent_time_ns, Sized(f.balls, kMaxSnapshotDetections),
     Sized(f.robots, kMaxSnapshotDetections));
}

template <class Io>
void Fields(Io& io, IoRef<Io, CameraRealism> c) {
  io(c.robot_position_stddev, c.robot_orientation_stddev, c.ball_position_stddev, c.robot_vanish, c.ball_vanish,
     c.confidence_spread, c.processing_delay, c.ball_occlusion, c.link);
  io.Check(CheckCameraRealism(c)[0] == '\0', "invalid camera realism");
}

template <class Io>
void Fields(Io& io, IoRef<Io, SensorRealism> r) {
  io(r.camera, r.command, r.encoder.resolution, r.encoder.noise_stddev, r.encoder.link, r.imu.gyro_bias,
     r.imu.gyro_noise_stddev, r.imu.accel_bias, r.imu.accel_noise_stddev, r.imu.link, r.touch.link);
  io.Check(CheckRealism(r)[0] == '\0', "invalid sensor realism");
}

}  // namespace turf
