#include "core/joint_sensors.h"

#include <cmath>

namespace turf {

double MeasureJoint(double angle, const EncoderRealism& e, Rng& rng) {
  const double quantised = e.resolution > 0.0 ? e.resolution * std::round(angle / e.resolution) : angle;
  return quantised + rng.Normal(0.0, e.noise_stddev);
}

namespace {
Vec3 Measure(const Vec3& v, double bias, double noise, Rng& rng) {
  const double nx = rng.Normal(0.0, noise), ny = rng.Normal(0.0, noise), nz = rng.Normal(0.0, noise);
  return {v.x + bias + nx, v.y + bias + ny, v.z + bias + nz};
}
}  // namespace

Vec3 MeasureGyro(const Vec3& rate, const ImuRealism& imu, Rng& rng) {
  return Measure(rate, imu.gyro_bias, imu.gyro_noise_stddev, rng);
}

Vec3 MeasureAccel(const Vec3& accel, const ImuRealism& imu, Rng& rng) {
  return Measure(accel, imu.accel_bias, imu.accel_noise_stddev, rng);
}

}  // namespace turf
