#include "core/sensor_realism.h"

#include <cmath>

namespace turf {

const char* CheckRealism(const SensorRealism& r) {
  auto nonneg = [](double v, double max) { return std::isfinite(v) && v >= 0.0 && v <= max; };
  const CameraRealism& c = r.camera;
  if (!nonneg(c.robot_position_stddev, 1.0) || !nonneg(c.ball_position_stddev, 1.0))
    return "camera position noise must be in [0, 1] m";
  if (!nonneg(c.robot_orientation_stddev, M_PI)) return "camera orientation noise must be in [0, pi] rad";
  if (!nonneg(c.robot_vanish, 1.0) || !nonneg(c.ball_vanish, 1.0)) return "vanish probabilities must be in [0, 1]";
  if (!nonneg(c.confidence_spread, 10.0)) return "confidence_spread must be in [0, 10]";
  if (!nonneg(c.processing_delay, 10.0)) return "processing_delay must be in [0, 10] s";
  if (const char* e = CheckLinkParams(c.link); *e != '\0') return e;
  if (const char* e = CheckLinkParams(r.command); *e != '\0') return e;
  if (!nonneg(r.encoder.resolution, 1.0) || !nonneg(r.encoder.noise_stddev, 1.0))
    return "encoder resolution and noise must be in [0, 1] rad";
  if (!std::isfinite(r.imu.gyro_bias) || !std::isfinite(r.imu.accel_bias) || !nonneg(r.imu.gyro_noise_stddev, 100) ||
      !nonneg(r.imu.accel_noise_stddev, 1000))
    return "IMU bias and noise must be finite and the noise >= 0";
  for (const LinkParams* link : {&r.encoder.link, &r.imu.link, &r.touch.link}) {
    if (const char* e = CheckLinkParams(*link); *e != '\0') return e;
  }
  return "";
}

}  // namespace turf
