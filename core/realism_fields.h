// Every sensor-realism parameter, once (a MuJoCo-style X-macro): its enum
// constant, its dotted name (the YAML keys of loader/realism_yaml.h), the
// IDL's RealismParameter constant (idl/SimControl.idl, same order: checked at
// compile time in participants/sim/control_loop.cpp and by a test reading the
// IDL), its place in a SensorRealism, unit, accepted range and meaning.
// OP_SET_REALISM's typed values, the README's realism table and the SSL
// simulation codec's mapping are all written in these names.
// Bools are 0/1 and jitter kinds 0..2 (JitterKind) when read as a number.
// The ranges are CheckRealism's (core/sensor_realism.cpp); a test holds them
// together. New rows go at the end (the IDL follows this order).
//   X(enumerator, name, IDL constant, member of SensorRealism, unit, min, max, meaning)
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <string_view>

#include "core/errors.h"
#include "core/sensor_realism.h"

// The nine parameters of one LinkParams at `member`, named `name`.<field>.
#define TURF_REALISM_LINK_FIELDS(X, e, name, idl, member, what)                                                       \
  X(e##Latency, name ".latency", idl##_LATENCY, member.latency, "s", 0.0, 10.0, "fixed delay of " what)               \
  X(e##Jitter, name ".jitter", idl##_JITTER, member.jitter, "s", 0.0, 10.0,                                           \
    "delay spread: stddev (gaussian), half width (uniform), mean (exponential)")                                      \
  X(e##JitterKind, name ".jitter_kind", idl##_JITTER_KIND, member.jitter_kind, "0..2", 0.0, 2.0,                      \
    "jitter distribution: 0 gaussian, 1 uniform, 2 exponential")                                                      \
  X(e##Loss, name ".loss", idl##_LOSS, member.loss, "1", 0.0, 1.0, "independent loss probability")                    \
  X(e##BurstEnabled, name ".burst.enabled", idl##_BURST_ENABLED, member.burst.enabled, "0/1", 0.0, 1.0,               \
    "Gilbert-Elliott burst loss instead of `loss` (YAML: a `burst` map is present)")                                  \
  X(e##BurstPGoodToBad, name ".burst.p_good_to_bad", idl##_BURST_P_GOOD_TO_BAD, member.burst.p_good_to_bad, "1", 0.0, \
    1.0, "per sample, good to bad state")                                                                             \
  X(e##BurstPBadToGood, name ".burst.p_bad_to_good", idl##_BURST_P_BAD_TO_GOOD, member.burst.p_bad_to_good, "1", 0.0, \
    1.0, "per sample, bad to good state (mean burst: 1/p samples; > 0 when enabled)")                                 \
  X(e##BurstLossGood, name ".burst.loss_good", idl##_BURST_LOSS_GOOD, member.burst.loss_good, "1", 0.0, 1.0,          \
    "loss probability in the good state")                                                                             \
  X(e##BurstLossBad, name ".burst.loss_bad", idl##_BURST_LOSS_BAD, member.burst.loss_bad, "1", 0.0, 1.0,              \
    "loss probability in the bad state")

#define TURF_REALISM_UNBOUNDED std::numeric_limits<double>::infinity()

#define TURF_REALISM_FIELDS(X)                                                                                        \
  X(kCameraRobotPositionStddev, "camera.robot_position_stddev", REALISM_CAMERA_ROBOT_POSITION_STDDEV,                 \
    camera.robot_position_stddev, "m", 0.0, 1.0, "robot position noise per axis")                                     \
  X(kCameraRobotOrientationStddev, "camera.robot_orientation_stddev", REALISM_CAMERA_ROBOT_ORIENTATION_STDDEV,        \
    camera.robot_orientation_stddev, "rad", 0.0, M_PI, "robot orientation noise")                                     \
  X(kCameraBallPositionStddev, "camera.ball_position_stddev", REALISM_CAMERA_BALL_POSITION_STDDEV,                    \
    camera.ball_position_stddev, "m", 0.0, 1.0, "ball position noise per axis")                                       \
  X(kCameraRobotVanish, "camera.robot_vanish", REALISM_CAMERA_ROBOT_VANISH, camera.robot_vanish, "1", 0.0, 1.0,       \
    "probability a robot is missing from a camera frame")                                                             \
  X(kCameraBallVanish, "camera.ball_vanish", REALISM_CAMERA_BALL_VANISH, camera.ball_vanish, "1", 0.0, 1.0,           \
    "probability the ball is missing from a camera frame")                                                            \
  X(kCameraBallOcclusion, "camera.ball_occlusion", REALISM_CAMERA_BALL_OCCLUSION, camera.ball_occlusion, "0/1", 0.0,  \
    1.0, "hide the ball behind robots, seen from the camera")                                                         \
  X(kCameraConfidenceSpread, "camera.confidence_spread", REALISM_CAMERA_CONFIDENCE_SPREAD, camera.confidence_spread,  \
    "1", 0.0, 10.0, "confidence = 1 - spread * abs(N(0,1)), at least 0.05")                                           \
  X(kCameraProcessingDelay, "camera.processing_delay", REALISM_CAMERA_PROCESSING_DELAY, camera.processing_delay, "s", \
    0.0, 10.0, "capture to sending (t_sent - t_capture)")                                                             \
  TURF_REALISM_LINK_FIELDS(X, kCameraLink, "camera.link", REALISM_CAMERA_LINK, camera.link,                           \
                           "each camera's frames to the network")                                                     \
  TURF_REALISM_LINK_FIELDS(X, kCommand, "command", REALISM_COMMAND, command, "a team's commands to its robots")       \
  X(kEncoderResolution, "encoder.resolution", REALISM_ENCODER_RESOLUTION, encoder.resolution, "rad", 0.0, 1.0,        \
    "joint angle quantisation step")                                                                                  \
  X(kEncoderNoiseStddev, "encoder.noise_stddev", REALISM_ENCODER_NOISE_STDDEV, encoder.noise_stddev, "rad", 0.0, 1.0, \
    "joint angle noise")                                                                                              \
  TURF_REALISM_LINK_FIELDS(X, kEncoderLink, "encoder.link", REALISM_ENCODER_LINK, encoder.link,                       \
                           "the joint-state stream")                                                                  \
  X(kImuGyroBias, "imu.gyro_bias", REALISM_IMU_GYRO_BIAS, imu.gyro_bias, "rad/s", -TURF_REALISM_UNBOUNDED,            \
    TURF_REALISM_UNBOUNDED, "constant gyro bias per axis")                                                            \
  X(kImuGyroNoiseStddev, "imu.gyro_noise_stddev", REALISM_IMU_GYRO_NOISE_STDDEV, imu.gyro_noise_stddev, "rad/s", 0.0, \
    100.0, "gyro noise per axis")                                                                                     \
  X(kImuAccelBias, "imu.accel_bias", REALISM_IMU_ACCEL_BIAS, imu.accel_bias, "m/s^2", -TURF_REALISM_UNBOUNDED,        \
    TURF_REALISM_UNBOUNDED, "constant accelerometer bias per axis")                                                   \
  X(kImuAccelNoiseStddev, "imu.accel_noise_stddev", REALISM_IMU_ACCEL_NOISE_STDDEV, imu.accel_noise_stddev, "m/s^2",  \
    0.0, 1000.0, "accelerometer noise per axis")                                                                      \
  TURF_REALISM_LINK_FIELDS(X, kImuLink, "imu.link", REALISM_IMU_LINK, imu.link, "the IMU stream")                     \
  TURF_REALISM_LINK_FIELDS(X, kTouchLink, "touch.link", REALISM_TOUCH_LINK, touch.link,                               \
                           "the foot touch and force stream")

namespace turf {

enum class RealismField : uint8_t {
#define TURF_REALISM_FIELD_ENUM(e, name, idl, member, unit, min, max, meaning) e,
  TURF_REALISM_FIELDS(TURF_REALISM_FIELD_ENUM)
#undef TURF_REALISM_FIELD_ENUM
      kCount
};

inline constexpr size_t kRealismFieldCount = static_cast<size_t>(RealismField::kCount);

struct RealismFieldInfo {
  RealismField field;
  const char* name;      // "camera.link.latency"
  const char* idl_name;  // "REALISM_CAMERA_LINK_LATENCY"
  const char* unit;      // "s", "1" (a probability or factor), "0/1" (a bool), "0..2" (an enum)
  double min, max;       // accepted values (infinite: unbounded)
  const char* meaning;
};

// One entry per row, in the table's order.
extern const RealismFieldInfo kRealismFields[kRealismFieldCount];

const RealismFieldInfo& Info(RealismField field);
// The row of a dotted name; nullopt if there is none.
std::optional<RealismField> RealismFieldNamed(std::string_view name);

// A parameter as a number (bools 0/1, jitter kinds their JitterKind value).
double GetRealismField(const SensorRealism& realism, RealismField field);
// Sets one parameter, or refuses (and changes nothing): kNotFinite (NaN,
// infinite), kUnknownEnum (a jitter kind that is no JitterKind), kOutOfRange
// (outside the row's range, or a bool not 0 or 1).
Error SetRealismField(SensorRealism* realism, RealismField field, double value);

// The README's table of realism parameters (name, unit, range, meaning).
std::string RealismFieldsMarkdown();

}  // namespace turf
