// How real the sensors and links are: the parameters of every value and link
// model. Part of the scene (and its presets in configs/realism/), changeable at
// run time. All zero means ideal: exact values, no delay, no loss.
#pragma once

#include "core/link_model.h"

namespace turf {

// SSL-Vision as a team sees it (cf. ER-Force's realism knobs).
struct CameraRealism {
  double robot_position_stddev = 0.0;     // m, per axis
  double robot_orientation_stddev = 0.0;  // rad
  double ball_position_stddev = 0.0;      // m, per axis
  double robot_vanish = 0.0;              // probability a robot is missing from a camera frame
  double ball_vanish = 0.0;               // likewise for the ball
  bool ball_occlusion = false;            // hide the ball behind robots, seen from the camera
  double confidence_spread = 0.0;         // confidence = 1 - spread * |N(0,1)|, at least 0.05
  double processing_delay = 0.0;          // s from capture to sending (t_sent - t_capture)
  LinkParams link;                        // vision system to the network, per camera
};

// Joint encoders: quantised to `resolution` (rad), plus Gaussian noise; the
// joint-state stream's link (robot bus to the network).
struct EncoderRealism {
  double resolution = 0.0;
  double noise_stddev = 0.0;
  LinkParams link;
};

// IMU: a constant bias plus Gaussian noise, per axis.
struct ImuRealism {
  double gyro_bias = 0.0;  // rad/s
  double gyro_noise_stddev = 0.0;
  double accel_bias = 0.0;  // m/s^2
  double accel_noise_stddev = 0.0;
  LinkParams link;  // the IMU stream's link
};

// Foot touch and force sensors: exact values; the stream's link.
struct TouchRealism {
  LinkParams link;
};

struct SensorRealism {
  CameraRealism camera;
  LinkParams command;  // a team's radio link to its robots
  EncoderRealism encoder;
  ImuRealism imu;
  TouchRealism touch;
};

// Why the parameters are unusable; empty when they are fine.
const char* CheckRealism(const SensorRealism& realism);
const char* CheckCameraRealism(const CameraRealism& camera);

}  // namespace turf
