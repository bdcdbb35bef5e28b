// LeggedWorld's per-robot and per-joint bookkeeping, shared by its source files (legged_world.cpp: set-up, state,
// snapshot; legged_world_motors.cpp: the motor and stop stages). Private to them: not part of core's interface.
#pragma once

#include <string>
#include <vector>

#include "core/legged/legged_world.h"

namespace turf {

struct LeggedWorld::JointSlot {
  std::string name;  // without the robot prefix
  int id = 0;        // the model's joint id
  int qpos = 0;
  int dof = 0;
  bool limited = false;
  double lo = 0.0;
  double hi = 0.0;
  double effort_limit = 0.0;    // N m: PD mode's torque bound
  double frictionloss = 0.0;    // the robot file's passive friction (PD mode keeps it)
  double start_position = 0.0;  // the scene's start angle (the model's qpos0 if none)
  JointCommand start;           // the command it holds at the start and after a reset
  JointCommand command;         // the holding command (joint name unused)
  double reference = 0.0;       // velocity mode: integrated target angle
  double effort = 0.0;          // the motor row's force in the last step
  int row = -1;                 // its motor's constraint row in this step, -1 if none
  // ODE stops (scene joint_stops): the stop found at the start of the last ODE step (0 none, 1 low, 2 high) and
  // the target velocity of its row (rad/s).
  int stop = 0;
  double stop_target = 0.0;
  int stop_row = -1;     // its limit row in this step, -1 if none
  double impulse = 0.0;  // N m s: what the velocity motor spent in this impulse window
  // The angle and speed the robot's state reports, read when MuJoCo computes its sensors (SenseJoints): at the
  // start of the last step (after it with the scene's sensors_after_step), as the IMU and every other sensor.
  double sensed_q = 0.0;
  double sensed_qd = 0.0;
};

struct LeggedWorld::SensorRef {
  std::string name;
  int adr = 0;
  int dim = 0;
  int site = -1;  // touch sensors: their site
};

struct LeggedWorld::RobotSlot {
  const LeggedRobot* spec = nullptr;
  int base_body = -1;
  int root_qpos = -1;  // the base's free joint, -1 if the robot is fixed to the world
  int root_dof = -1;
  std::vector<int> bodies;              // every body of the robot
  std::vector<std::string> body_names;  // without the robot prefix
  std::vector<JointSlot> joints;
  int gyro = -1;  // sensordata addresses, -1 if absent
  int accelerometer = -1;
  int orientation = -1;
  std::vector<SensorRef> forces;
  int qpos_begin = 0;  // the robot's slices of qpos and qvel (its joints are one run of each)
  int qpos_end = 0;
  int dof_begin = 0;
  int dof_end = 0;
  std::vector<int> geoms;  // its collision geoms
};

}  // namespace turf
