// ActuatorRequests as a team program builds them (turf's hlvs.proto): sensor time steps and a motor position.
#pragma once

#include <cstdint>
#include <initializer_list>
#include <string>
#include <utility>

#include "codecs/proto/hlvs.pb.h"

namespace turf::test {

// Each named sensor every `ms` milliseconds (0: off).
inline hlvs::pb::ActuatorRequests TimeSteps(std::initializer_list<std::pair<const char*, uint32_t>> steps) {
  hlvs::pb::ActuatorRequests r;
  for (const auto& [name, ms] : steps) {
    hlvs::pb::SensorTimeStep* s = r.add_sensor_time_steps();
    s->set_name(name);
    s->set_timestep(ms);
  }
  return r;
}

// One motor to `position` (rad).
inline hlvs::pb::ActuatorRequests Position(const std::string& motor, double position) {
  hlvs::pb::ActuatorRequests r;
  hlvs::pb::MotorPosition* p = r.add_motor_positions();
  p->set_name(motor);
  p->set_position(position);
  return r;
}

}  // namespace turf::test
