#include "participants/sim/legged_convert.h"

#include <utility>

#include "participants/sim/enum_table.h"

namespace turf {

idl::GeomShape ToIdl(LeggedGeom::Shape shape) {
  switch (shape) {
    case LeggedGeom::Shape::kBox:
      return idl::GEOM_BOX;
    case LeggedGeom::Shape::kSphere:
      return idl::GEOM_SPHERE;
    case LeggedGeom::Shape::kCapsule:
      return idl::GEOM_CAPSULE;
    case LeggedGeom::Shape::kCylinder:
      return idl::GEOM_CYLINDER;
    case LeggedGeom::Shape::kEllipsoid:
      return idl::GEOM_ELLIPSOID;
    case LeggedGeom::Shape::kOther:
      break;
  }
  return idl::GEOM_OTHER;
}

void FillJoints(const LeggedRobotState& r, int64_t time_ns, uint64_t frame, idl::JointState* joints) {
  joints->robot(r.name);
  joints->id(r.id);
  joints->sim_time_ns(time_ns);
  joints->frame(frame);
  joints->name(r.joint_names);
  joints->position(r.joint_positions);
  joints->velocity(r.joint_velocities);
  joints->effort(r.joint_efforts);
}

void FillImu(const LeggedRobotState& r, int64_t time_ns, idl::ImuState* imu) {
  imu->robot(r.name);
  imu->sim_time_ns(time_ns);
  imu->valid(r.has_imu);
  imu->orientation(Q4(r.orientation));
  imu->angular_velocity(V3(r.gyro));
  imu->linear_acceleration(V3(r.accelerometer));
  imu->base_position(V3(r.base_position));
  imu->base_orientation(Q4(r.base_orientation));
  imu->base_velocity(V3(r.base_velocity));
}

void FillForce(const LeggedRobotState& r, int64_t time_ns, idl::ForceState* force) {
  force->robot(r.name);
  force->sim_time_ns(time_ns);
  force->sensors().resize(r.forces.size());
  for (size_t f = 0; f < r.forces.size(); ++f) {
    idl::ForceReading& reading = force->sensors()[f];
    reading.name(r.forces[f].name);
    reading.values(r.forces[f].values);
    reading.contact(r.forces[f].contact);
    reading.force(V3(r.forces[f].force));
    reading.point(V3(r.forces[f].point));
  }
}

void FillLinks(const LeggedRobotState& r, int64_t time_ns, uint64_t frame, idl::LinkState* links) {
  links->robot(r.name);
  links->sim_time_ns(time_ns);
  links->frame(frame);
  links->links().resize(r.links.size());
  for (size_t l = 0; l < r.links.size(); ++l) {
    links->links()[l].name(r.links[l].name);
    links->links()[l].position(V3(r.links[l].position));
    links->links()[l].orientation(Q4(r.links[l].orientation));
  }
}

void FillState(const LeggedWorldState& state, idl::LeggedState* out) {
  const size_t n = state.robots.size();
  out->sim_time_ns(state.time_ns);
  out->frame(state.frame);
  out->joints().resize(n);
  out->imu().resize(n);
  out->force().resize(n);
  out->links().resize(n);
  for (size_t i = 0; i < n; ++i) {
    const LeggedRobotState& r = state.robots[i];
    FillJoints(r, state.time_ns, state.frame, &out->joints()[i]);
    FillImu(r, state.time_ns, &out->imu()[i]);
    FillForce(r, state.time_ns, &out->force()[i]);
    FillLinks(r, state.time_ns, state.frame, &out->links()[i]);
  }
  out->has_ball(state.has_ball);
  out->ball_position(V3(state.ball_position));
  out->ball_velocity(V3(state.ball_velocity));
  out->robot_contacts().resize(state.robot_contacts.size());
  for (size_t c = 0; c < state.robot_contacts.size(); ++c) {
    const RobotContact& in = state.robot_contacts[c];
    idl::RobotContact& contact = out->robot_contacts()[c];
    contact.robot_a(state.robots[in.robot_a].name);
    contact.robot_b(state.robots[in.robot_b].name);
    contact.point(V3(in.point));
    contact.points(static_cast<uint32_t>(in.points));
  }
  out->ball_touches().clear();
  for (const LeggedRobotState& r : state.robots) {
    if (r.ball_touch_ns < 0) continue;
    idl::BallTouch touch;
    touch.robot(r.name);
    touch.sim_time_ns(r.ball_touch_ns);
    out->ball_touches().push_back(touch);
  }
}

bool FromIdl(const idl::JointTarget& in, JointCommand* out) {
  out->joint = in.name();
  static constexpr std::pair<idl::JointMode, JointMode> kModes[] = {{idl::JOINT_VELOCITY, JointMode::kVelocity},
                                                                    {idl::JOINT_POSITION, JointMode::kPosition},
                                                                    {idl::JOINT_TORQUE, JointMode::kTorque},
                                                                    {idl::JOINT_PD, JointMode::kPd}};
  if (!FromIdlEnum(kModes, in.mode(), &out->mode)) return false;
  out->value = in.value();
  out->kp = in.kp();
  out->kd = in.kd();
  out->dq = in.dq();
  out->tau = in.tau();
  return true;
}

}  // namespace turf
