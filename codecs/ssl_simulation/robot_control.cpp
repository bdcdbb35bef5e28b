#include "codecs/ssl_simulation/robot_control.h"

#include <algorithm>
#include <bitset>
#include <cmath>
#include <string>

#include "core/input_limits.h"
#include "idl/values.h"

namespace turf::simproto {

namespace ws = wire::simulation;

namespace {

using idl::V3;

constexpr double kDegToRad = M_PI / 180.0;
constexpr double kMaxKickAngleDeg = 90.0;  // exclusive: a chip needs some forward speed

const char* TeamName(idl::Team team) { return team == idl::TEAM_BLUE ? "blue" : "yellow"; }

// The turf robot a wire id means on `port`; false if it cannot be one.
bool MapId(uint32_t wire_id, Port port, int robots_per_team, idl::Team* team, uint8_t* id, std::string* why) {
  uint32_t local = wire_id;
  switch (port) {
    case Port::kBlue:
      *team = idl::TEAM_BLUE;
      break;
    case Port::kYellow:
      *team = idl::TEAM_YELLOW;
      break;
    case Port::kSync:
      *team = wire_id >= kSyncYellowOffset ? idl::TEAM_YELLOW : idl::TEAM_BLUE;
      if (wire_id >= kSyncYellowOffset) local = wire_id - kSyncYellowOffset;
      break;
  }
  if (local > kMaxWireRobotId || static_cast<int>(local) >= robots_per_team) {
    *why = "robot id " + std::to_string(wire_id) + ": " + TeamName(*team) + " has ids 0.." +
           std::to_string(std::min<int>(robots_per_team, kMaxWireRobotId + 1) - 1) +
           (port == Port::kSync ? " (sync port: ids 16..31 are yellow)" : "");
    return false;
  }
  *id = static_cast<uint8_t>(local);
  return true;
}

// `who`'s velocity command `what` ("local_velocity (forward, left)"): x, y in m/s and z the angular speed.
void CheckVelocity(const idl::Vec3& v, const std::string& who, const char* what, Problems* p) {
  const double x = v.x(), y = v.y(), angular = v.z();
  bool ok = p->Check(x, -kMaxCommandSpeed, kMaxCommandSpeed, who, ": ", what, ".x");
  ok = p->Check(y, -kMaxCommandSpeed, kMaxCommandSpeed, who, ": ", what, ".y") && ok;
  ok = p->Check(angular, -kMaxCommandAngularSpeed, kMaxCommandAngularSpeed, who, ": ", what, ".angular") && ok;
  if (ok && std::hypot(x, y) > kMaxCommandSpeed)
    p->Add(DecodeError::kOutOfRange, who + ": " + what + ": speed above " + std::to_string(kMaxCommandSpeed) + " m/s");
}

void ConvertMove(const ws::RobotCommand& in, const std::string& who, idl::SslRobotCommand* out, Problems* p) {
  const ws::RobotMoveCommand& move = in.move_command();
  switch (move.command_case()) {
    case ws::RobotMoveCommand::kWheelVelocity: {
      const ws::MoveWheelVelocity& w = move.wheel_velocity();
      const double wheels[4] = {w.front_right(), w.back_right(), w.back_left(), w.front_left()};
      const char* names[4] = {"front_right", "back_right", "back_left", "front_left"};
      for (int i = 0; i < 4; ++i)
        p->Check(wheels[i], -kMaxCommandSpeed, kMaxCommandSpeed, who, ": wheel_velocity.", names[i]);
      out->move(idl::MOVE_WHEEL_VELOCITY);
      out->wheel_velocity({wheels[0], wheels[1], wheels[2], wheels[3]});
      break;
    }
    case ws::RobotMoveCommand::kLocalVelocity: {
      const ws::MoveLocalVelocity& v = move.local_velocity();
      const idl::Vec3 velocity = V3(v.forward(), v.left(), v.angular());
      CheckVelocity(velocity, who, "local_velocity (forward, left)", p);
      out->move(idl::MOVE_LOCAL_VELOCITY);
      out->velocity(velocity);
      break;
    }
    case ws::RobotMoveCommand::kGlobalVelocity: {
      const ws::MoveGlobalVelocity& v = move.global_velocity();
      const idl::Vec3 velocity = V3(v.x(), v.y(), v.angular());
      CheckVelocity(velocity, who, "global_velocity", p);
      out->move(idl::MOVE_GLOBAL_VELOCITY);
      out->velocity(velocity);
      break;
    }
    case ws::RobotMoveCommand::COMMAND_NOT_SET:
      out->move(idl::MOVE_NONE);
      break;
  }
}

void ConvertKickAndDribbler(const ws::RobotCommand& in, const std::string& who, idl::SslRobotCommand* out,
                            Problems* p) {
  const bool speed_ok = p->Check(in.kick_speed(), 0.0, kMaxKickSpeed, who, ": kick_speed");
  const bool angle_ok = p->Check(in.kick_angle(), 0.0, kMaxKickAngleDeg, who, ": kick_angle (degrees)");
  if (angle_ok && in.kick_angle() >= kMaxKickAngleDeg)
    p->Add(DecodeError::kOutOfRange, who + ": kick_angle must be below 90 degrees");
  if (speed_ok && in.kick_speed() > 0.0) {
    out->kick(in.kick_angle() > 0.0 ? idl::KICK_CHIP : idl::KICK_FLAT);
    out->kick_speed(in.kick_speed());
    out->chip_angle(in.kick_angle() > 0.0 ? in.kick_angle() * kDegToRad : 0.0);
  } else {
    out->kick(idl::KICK_NONE);
  }
  p->Check(in.dribbler_speed(), 0.0, kMaxDribblerSpeed, who, ": dribbler_speed (rpm)");
  out->dribbler_speed(in.dribbler_speed());
}

// Whether any message of `message` carries unknown fields, by the generated accessors (the reflective walk of
// errors.h costs ~20 times as much per message, on every command of every sync request).
bool AnyUnknownField(const ws::RobotControl& message) {
  if (!message.unknown_fields().empty()) return true;
  for (const ws::RobotCommand& c : message.robot_commands()) {
    if (!c.unknown_fields().empty()) return true;
    if (!c.has_move_command()) continue;
    const ws::RobotMoveCommand& m = c.move_command();
    if (!m.unknown_fields().empty()) return true;
    if (m.has_wheel_velocity() && !m.wheel_velocity().unknown_fields().empty()) return true;
    if (m.has_local_velocity() && !m.local_velocity().unknown_fields().empty()) return true;
    if (m.has_global_velocity() && !m.global_velocity().unknown_fields().empty()) return true;
  }
  return false;
}

}  // namespace

RobotControlDecode ConvertRobotControl(const ws::RobotControl& message, Port port, int robots_per_team) {
  RobotControlDecode out;
  Problems p;
  std::bitset<256> seen[2];  // by team, robot id
  for (const ws::RobotCommand& in : message.robot_commands()) {
    idl::SslRobotCommand c;
    idl::Team team = idl::TEAM_BLUE;
    uint8_t id = 0;
    std::string why;
    if (!MapId(in.id(), port, robots_per_team, &team, &id, &why)) {
      p.Add(DecodeError::kUnknownRobot, why);
      continue;
    }
    const std::string who = std::string(TeamName(team)) + " robot " + std::to_string(id);
    std::bitset<256>& team_seen = seen[team == idl::TEAM_BLUE ? 0 : 1];
    if (team_seen.test(id)) p.Add(DecodeError::kDuplicateRobot, who + " is commanded twice");
    team_seen.set(id);
    c.team(team);
    c.id(id);
    ConvertMove(in, who, &c, &p);
    ConvertKickAndDribbler(in, who, &c, &p);
    out.commands.push_back(c);
    out.wire_ids.push_back(in.id());
  }
  if (AnyUnknownField(message)) ReportUnknownFields(message, &p.errors());
  out.error = p.error();
  out.errors = std::move(p.errors());
  if (out.error != DecodeError::kOk) {
    out.commands.clear();
    out.wire_ids.clear();
  }
  return out;
}

RobotControlDecode DecodeRobotControl(const uint8_t* data, size_t size, Port port, int robots_per_team) {
  return ParseThen<ws::RobotControl, RobotControlDecode>(
      data, size, [&](const ws::RobotControl& message) { return ConvertRobotControl(message, port, robots_per_team); });
}

void FillRobotControlResponse(const RobotControlDecode& decoded, const ContactMap& contacts,
                              const std::vector<SimError>& extra, ws::RobotControlResponse* out) {
  for (size_t i = 0; i < decoded.commands.size(); ++i) {
    const idl::SslRobotCommand& c = decoded.commands[i];
    ws::RobotFeedback* f = out->add_feedback();
    f->set_id(decoded.wire_ids[i]);
    const auto it = contacts.find({c.team(), c.id()});
    f->set_dribbler_ball_contact(it != contacts.end() && it->second);
  }
  AppendErrors(decoded.errors, out->mutable_errors());
  AppendErrors(extra, out->mutable_errors());
}

std::vector<uint8_t> EncodeRobotControlResponse(const RobotControlDecode& decoded, const ContactMap& contacts,
                                                const std::vector<SimError>& extra) {
  ws::RobotControlResponse response;
  FillRobotControlResponse(decoded, contacts, extra, &response);
  std::vector<uint8_t> bytes(response.ByteSizeLong());
  response.SerializeToArray(bytes.data(), static_cast<int>(bytes.size()));
  return bytes;
}

}  // namespace turf::simproto
