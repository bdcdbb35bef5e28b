#include "core/sensor_realism.h"

#include <cmath>

namespace turf {

namespace {

bool NonNegative(double v, double max) { return std::isfinite(v) && v >= 0.0 && v <= max; }

}  // namespace

const char* CheckCameraRealism(const CameraRealism& c) {
  if (!NonNegative(c.robot_position_stddev, 1.0) || !NonNegative(c.ball_position_stddev, 1.0))
    return "camera position noise must be in [0, 1] m";
  if (!NonNegative(c.robot_orientation_stddev, M_PI)) return "camera orientation noise must be in [0, pi] rad";
  if (!NonNegative(c.robot_vanish, 1.0) || !NonNegative(c.ball_vanish, 1.0))
    return "vanish probabilities must be in [0, 1]";
  if (!NonNegative(c.confidence_spread, 10.0)) return "confidence_spread must be in [0, 10]";
  if (!NonNegative(c.processing_delay, 10.0)) return "processing_delay must be in [0, 10] s";
  return CheckLinkParams(c.link);
}

const char* CheckRealism(const SensorRealism& r) {
  if (const char* e = CheckCameraRealism(r.camera); *e != '\0') return e;
  if (const char* e = CheckLinkParams(r.command); *e != '\0') return e;
  if (!NonNegative(r.encoder.resolution, 1.0) || !NonNegative(r.encoder.noise_stddev, 1.0))
    return "encoder resolution and noise must be in [0, 1] rad";
  if (!std::isfinite(r.imu.gyro_bias) || !std::isfinite(r.imu.accel_bias) ||
      !NonNegative(r.imu.gyro_noise_stddev, 100) || !NonNegative(r.imu.accel_noise_stddev, 1000))
    return "IMU bias and noise must be finite and the noise >= 0";
  for (const LinkParams* link : {&r.encoder.link, &r.imu.link, &r.touch.link}) {
    if (const char* e = CheckLinkParams(*link); *e != '\0') return e;
  }
  return "";
}

}  // namespace turf
