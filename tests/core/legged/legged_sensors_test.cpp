// The encoder and IMU models applied to legged robots (core/legged/legged_sensors.h).
#include "core/legged/legged_sensors.h"

#include <gtest/gtest.h>

#include <cmath>

#include "tests/core/legged/nao_fixture.h"

namespace turf {
namespace {

using testing::NaoScene;

TEST(LeggedSensorsTest, IdealRealismLeavesTheStateExact) {
  LeggedWorld w(NaoScene());
  w.SetJointCommand(0, {"hj1", JointMode::kVelocity, 1.0});
  for (int i = 0; i < 100; ++i) w.Step();
  const LeggedWorldState truth = w.State();
  LeggedWorldState s = truth;
  LeggedSensors sensors(1, {"nao_1"});
  sensors.Apply(SensorRealism{}, &s);
  EXPECT_EQ(s.robots[0].joint_positions, truth.robots[0].joint_positions);
  EXPECT_EQ(s.robots[0].gyro, truth.robots[0].gyro);
  EXPECT_EQ(s.robots[0].accelerometer, truth.robots[0].accelerometer);
}

TEST(LeggedSensorsTest, EncodersQuantiseAndAddNoiseWithTheGivenSpread) {
  LeggedWorld w(NaoScene());
  w.SetJointCommand(0, {"hj1", JointMode::kVelocity, 1.0});
  for (int i = 0; i < 100; ++i) w.Step();
  const LeggedWorldState truth = w.State();
  LeggedSensors sensors(1, {"nao_1"});
  SensorRealism quantised;
  quantised.encoder.resolution = 0.01;
  LeggedWorldState s = truth;
  sensors.Apply(quantised, &s);
  for (size_t j = 0; j < s.robots[0].joint_positions.size(); ++j) {
    const double q = s.robots[0].joint_positions[j];
    EXPECT_NEAR(q / 0.01, std::round(q / 0.01), 1e-9);
    EXPECT_LE(std::abs(q - truth.robots[0].joint_positions[j]), 0.005 + 1e-12);
  }
  // Noise: hj1 at 20,000 frames, stddev within 3 %.
  SensorRealism noisy;
  noisy.encoder.noise_stddev = 0.002;
  const size_t hj1 = static_cast<size_t>(w.JointIndex(0, "hj1"));
  double sum = 0.0, sum2 = 0.0;
  const int n = 20000;
  for (int i = 0; i < n; ++i) {
    LeggedWorldState r = truth;
    r.frame = static_cast<uint64_t>(i);
    sensors.Apply(noisy, &r);
    const double e = r.robots[0].joint_positions[hj1] - truth.robots[0].joint_positions[hj1];
    sum += e;
    sum2 += e * e;
  }
  const double mean = sum / n;
  const double stddev = std::sqrt(sum2 / n - mean * mean);
  EXPECT_NEAR(mean, 0.0, 4 * 0.002 / std::sqrt(n));
  EXPECT_NEAR(stddev, 0.002, 0.03 * 0.002);
}

TEST(LeggedSensorsTest, ImuBiasShiftsTheMeanAndNoiseIsAFunctionOfSeedRobotAndFrame) {
  LeggedWorld w(NaoScene(2));
  for (int i = 0; i < 200; ++i) w.Step();
  const LeggedWorldState truth = w.State();
  SensorRealism imu;
  imu.imu.accel_bias = 0.3;
  imu.imu.accel_noise_stddev = 0.05;
  imu.imu.gyro_noise_stddev = 0.01;
  LeggedSensors a(7, {"nao_1", "nao_2"});
  LeggedSensors b(7, {"nao_1", "nao_2"});
  double mean_z = 0.0;
  const int n = 5000;
  LeggedWorldState first;
  for (int i = 0; i < n; ++i) {
    LeggedWorldState ra = truth;
    ra.frame = static_cast<uint64_t>(i);
    LeggedWorldState rb = ra;
    a.Apply(imu, &ra);
    b.Apply(imu, &rb);
    ASSERT_EQ(ra.robots[1].accelerometer, rb.robots[1].accelerometer);  // same seed: same readings
    ASSERT_NE(ra.robots[0].gyro, ra.robots[1].gyro);                    // robots have their own streams
    mean_z += ra.robots[0].accelerometer[2] - truth.robots[0].accelerometer[2];
    if (i == 0) first = ra;
  }
  EXPECT_NEAR(mean_z / n, 0.3, 4 * 0.05 / std::sqrt(n));
  // Measuring frame 0 again, after 5,000 other measurements, reads the same.
  LeggedWorldState again = truth;
  again.frame = 0;
  a.Apply(imu, &again);
  EXPECT_EQ(again.robots[0].gyro, first.robots[0].gyro);
  LeggedWorldState next = truth;
  next.frame = 1;
  a.Apply(imu, &next);
  EXPECT_NE(next.robots[0].gyro, first.robots[0].gyro);
}

}  // namespace
}  // namespace turf
