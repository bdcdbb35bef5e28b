#include "codecs/ssl_vision/tracked.h"

#include <cmath>
#include <initializer_list>

#include "codecs/ssl_vision/detection.h"

namespace turf::vision {

namespace {

constexpr double kMaxCoordinate = 1000.0;  // m
constexpr double kMaxSpeed = 1000.0;       // m/s and rad/s
constexpr double kTwoPi = 6.283185307179586;

VisionError CheckVec(std::initializer_list<double> values, double limit) {
  for (double v : values) {
    if (!std::isfinite(v)) return VisionError::kNotFinite;
    if (std::abs(v) > limit) return VisionError::kOutOfRange;
  }
  return VisionError::kOk;
}

VisionError CheckVec3(const idl::Vec3& v, double limit) { return CheckVec({v.x(), v.y(), v.z()}, limit); }

void Set(const idl::Vec3& in, wire::vision::Vector3* out) {
  out->set_x(static_cast<float>(in.x()));
  out->set_y(static_cast<float>(in.y()));
  out->set_z(static_cast<float>(in.z()));
}

void Set(double x, double y, wire::vision::Vector2* out) {
  out->set_x(static_cast<float>(x));
  out->set_y(static_cast<float>(y));
}

}  // namespace

VisionError CheckWorldState(const idl::WorldState& state) {
  VisionError e = CheckVec3(state.ball().position(), kMaxCoordinate);
  if (e == VisionError::kOk) e = CheckVec3(state.ball().velocity(), kMaxSpeed);
  if (e != VisionError::kOk) return e;
  if (state.robots().size() > kMaxDetections) return VisionError::kTooMany;
  for (const idl::RobotState& r : state.robots()) {
    if (!r.on_field()) continue;  // a parked robot's pose is not sent
    e = CheckVec({r.position().x(), r.position().y(), r.yaw()}, kMaxCoordinate);
    if (e == VisionError::kOk) e = CheckVec3(r.linear_velocity(), kMaxSpeed);
    if (e == VisionError::kOk) e = CheckVec3(r.angular_velocity(), kMaxSpeed);
    if (e != VisionError::kOk) return e;
    if (r.team() != idl::TEAM_BLUE && r.team() != idl::TEAM_YELLOW) return VisionError::kUnknownTeam;
    if (r.id() > kMaxRobotId) return VisionError::kBadRobotId;
  }
  return VisionError::kOk;
}

void FillTracked(const idl::WorldState& state, const TrackedSource& source, double timestamp,
                 wire::vision::TrackerWrapperPacket* out) {
  out->Clear();
  out->set_uuid(source.uuid);
  out->set_source_name(source.source_name);
  wire::vision::TrackedFrame* frame = out->mutable_tracked_frame();
  frame->set_frame_number(static_cast<uint32_t>(state.frame()));
  frame->set_timestamp(timestamp);
  wire::vision::TrackedBall* ball = frame->add_balls();
  Set(state.ball().position(), ball->mutable_pos());
  Set(state.ball().velocity(), ball->mutable_vel());
  ball->set_visibility(1.0f);
  for (const idl::RobotState& r : state.robots()) {
    if (!r.on_field()) continue;
    wire::vision::TrackedRobot* o = frame->add_robots();
    o->mutable_robot_id()->set_id(r.id());
    o->mutable_robot_id()->set_team_color(r.team() == idl::TEAM_YELLOW ? wire::vision::TEAM_COLOR_YELLOW
                                                                       : wire::vision::TEAM_COLOR_BLUE);
    Set(r.position().x(), r.position().y(), o->mutable_pos());
    o->set_orientation(static_cast<float>(std::remainder(r.yaw(), kTwoPi)));
    Set(r.linear_velocity().x(), r.linear_velocity().y(), o->mutable_vel());
    o->set_vel_angular(static_cast<float>(r.angular_velocity().z()));
    o->set_visibility(1.0f);
  }
  frame->add_capabilities(wire::vision::CAPABILITY_DETECT_FLYING_BALLS);
}

VisionError EncodeTracked(const idl::WorldState& state, const TrackedSource& source, double timestamp,
                          std::vector<uint8_t>* out) {
  out->clear();
  VisionError e = CheckWorldState(state);
  if (e == VisionError::kOk && !std::isfinite(timestamp)) e = VisionError::kNotFinite;
  if (e == VisionError::kOk && !(timestamp > 0.0)) e = VisionError::kTimeNotPositive;
  if (e != VisionError::kOk) return e;
  wire::vision::TrackerWrapperPacket packet;
  FillTracked(state, source, timestamp, &packet);
  out->resize(packet.ByteSizeLong());
  packet.SerializeToArray(out->data(), static_cast<int>(out->size()));
  return VisionError::kOk;
}

}  // namespace turf::vision
