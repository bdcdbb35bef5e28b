// Value models of robot-internal sensors (joint encoders, IMU), for scenes
// with jointed robots. Pure functions of the true value and a random stream.
#pragma once

#include "core/rng.h"
#include "core/sensor_realism.h"
#include "core/types.h"

namespace turf {

// An encoder reading: the angle quantised to the resolution, plus noise.
double MeasureJoint(double angle, const EncoderRealism& encoder, Rng& rng);

// Gyro and accelerometer readings: true value + bias + noise, per axis.
Vec3 MeasureGyro(const Vec3& rate, const ImuRealism& imu, Rng& rng);
Vec3 MeasureAccel(const Vec3& accel, const ImuRealism& imu, Rng& rng);

}  // namespace turf
