#include "codecs/ssl_simulation/simulator_command.h"

#include "codecs/ssl_simulation/realism.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <utility>

#include "core/input_limits.h"
#include "idl/values.h"

namespace turf::simproto {

namespace ws = wire::simulation;

namespace {

using idl::V2;
using idl::V3;

idl::SimControl Request(idl::ControlOp op) {
  idl::SimControl c;
  c.op(op);
  return c;
}

const idl::RobotState* FindRobot(const idl::WorldState* world, idl::Team team, uint8_t id) {
  if (world == nullptr) return nullptr;
  for (const idl::RobotState& r : world->robots())
    if (r.team() == team && r.id() == id) return &r;
  return nullptr;
}

// Walls, as turf-sim checks them: an object of `radius` must fit inside.
void CheckInsideWalls(double x, double y, double radius, const idl::SslField* field, const std::string& what,
                      Problems* p) {
  if (field == nullptr) return;  // turf-sim checks again
  const double max_x = field->field_length() / 2 + field->boundary_width_goal_line() - radius;
  const double max_y = field->field_width() / 2 + field->boundary_width() - radius;
  if (std::abs(x) > max_x || std::abs(y) > max_y)
    p->Add(DecodeError::kOutsideField, what + " (" + std::to_string(x) + ", " + std::to_string(y) +
                                           ") is beyond the walls (|x| <= " + std::to_string(max_x) +
                                           ", |y| <= " + std::to_string(max_y) + ")");
}

// The value of an optional coordinate, or the current one; false if neither.
bool Coordinate(bool has, float value, const std::string& what, const double* current, Problems* p, double* out) {
  if (has) {
    *out = value;
    return p->Check(value, -kMaxPlacementCoordinate, kMaxPlacementCoordinate, what);  // walls: on the pair
  }
  if (current != nullptr) {
    *out = *current;
    return true;
  }
  p->Add(DecodeError::kMissingRequired, what + " is absent and there is no current value to keep");
  return false;
}

bool Velocity(float vx, float vy, float vz, double max, const std::string& what, Problems* p) {
  bool ok = p->Check(vx, -max, max, what, ".x");
  ok = p->Check(vy, -max, max, what, ".y") && ok;
  ok = p->Check(vz, -max, max, what, ".z") && ok;
  return ok;
}

// Pushes robots out of the ball's way (teleport_safely).
void ClearBallTarget(const idl::BallTeleport& ball, const ControlContext& ctx,
                     const std::set<std::pair<idl::Team, uint8_t>>& teleported, std::vector<idl::SimControl>* out) {
  const idl::SslField& f = *ctx.field;
  if (ball.position().z() > f.robot_height() + f.ball_radius()) return;  // flies over every robot
  const double clear = f.max_robot_radius() + f.ball_radius() + kSafeTeleportMargin;
  const double max_x = f.field_length() / 2 + f.boundary_width_goal_line() - f.max_robot_radius();
  const double max_y = f.field_width() / 2 + f.boundary_width() - f.max_robot_radius();
  for (const idl::RobotState& r : ctx.world->robots()) {
    if (!r.on_field() || teleported.count({r.team(), r.id()}) > 0) continue;
    const double dx = r.position().x() - ball.position().x();
    const double dy = r.position().y() - ball.position().y();
    const double d = std::hypot(dx, dy);
    if (d >= clear) continue;
    // Straight away from the ball; a robot right on the target goes towards the field's centre.
    double ux = d > 1e-6 ? dx / d : (ball.position().x() > 0 ? -1.0 : 1.0);
    double uy = d > 1e-6 ? dy / d : 0.0;
    idl::SimControl c = Request(idl::OP_TELEPORT_ROBOT);
    c.robot().team(r.team());
    c.robot().id(r.id());
    c.robot().on_field(true);
    c.robot().position(V2(std::clamp(ball.position().x() + ux * clear, -max_x, max_x),
                          std::clamp(ball.position().y() + uy * clear, -max_y, max_y)));
    c.robot().orientation(r.yaw());
    out->push_back(c);
  }
}

void ConvertBall(const ws::TeleportBall& in, const ControlContext& ctx, Problems* p, std::vector<idl::SimControl>* out,
                 bool* safely) {
  if (in.by_force()) {
    p->AddUnsupported(kUnsupportedByForce,
                      "teleport_ball.by_force: turf cannot push the ball to a target; "
                      "the ball was not moved (send by_force false to teleport it)");
    return;
  }
  const idl::Vec3* now = ctx.world != nullptr ? &ctx.world->ball().position() : nullptr;
  const double cur[3] = {now ? now->x() : 0.0, now ? now->y() : 0.0, now ? now->z() : 0.0};
  double x = 0.0, y = 0.0, z = 0.0;
  bool ok = Coordinate(in.has_x(), in.x(), "teleport_ball.x", now ? &cur[0] : nullptr, p, &x);
  ok = Coordinate(in.has_y(), in.y(), "teleport_ball.y", now ? &cur[1] : nullptr, p, &y) && ok;
  ok = Coordinate(in.has_z(), in.z(), "teleport_ball.z", now ? &cur[2] : nullptr, p, &z) && ok;
  ok = Velocity(in.vx(), in.vy(), in.vz(), kMaxTeleportSpeed, "teleport_ball.v", p) && ok;
  if (!ok) return;
  const double radius = ctx.field != nullptr ? ctx.field->ball_radius() : 0.0;
  CheckInsideWalls(x, y, radius, ctx.field, "teleport_ball", p);
  if (z < 0.0 || z > kMaxTeleportHeight)
    p->Add(DecodeError::kOutsideField, "teleport_ball.z = " + std::to_string(z) + " is outside [0, 10] m");
  if (std::sqrt(in.vx() * in.vx() + in.vy() * in.vy() + in.vz() * in.vz()) > kMaxTeleportSpeed)
    p->Add(DecodeError::kOutOfRange, "teleport_ball speed above " + std::to_string(kMaxTeleportSpeed) + " m/s");
  // ER-Force's simulator, the protocol's reference, reads z as the ball's height above the carpet and adds its radius;
  // turf's control topic takes the centre's (an absent z keeps the centre where it is).
  if (in.has_z()) z += radius;
  idl::SimControl c = Request(idl::OP_TELEPORT_BALL);
  c.ball().position(V3(x, y, z));
  c.ball().velocity(V3(in.vx(), in.vy(), in.vz()));
  c.ball().roll(in.roll());
  out->push_back(c);
  *safely = in.teleport_safely();
  if (*safely && (ctx.field == nullptr || ctx.world == nullptr))
    p->Add(DecodeError::kMissingRequired, "teleport_ball.teleport_safely needs the world state, none known yet");
}

void ConvertRobot(const ws::TeleportRobot& in, int index, const ControlContext& ctx, Problems* p,
                  std::vector<idl::SimControl>* out) {
  const std::string at = "teleport_robot[" + std::to_string(index) + "]";
  if (!in.id().has_id()) return p->Add(DecodeError::kMissingRequired, at + ".id.id is absent");
  if (!in.id().has_team() || in.id().team() == ws::UNKNOWN)
    return p->Add(DecodeError::kUnknownRobot, at + ".id.team must be YELLOW or BLUE");
  const idl::Team team = in.id().team() == ws::BLUE ? idl::TEAM_BLUE : idl::TEAM_YELLOW;
  const int per_team = ctx.field != nullptr ? ctx.field->robots_per_team() : 16;
  if (in.id().id() > 15 || static_cast<int>(in.id().id()) >= per_team)
    return p->Add(DecodeError::kUnknownRobot, at + ": no robot " + std::to_string(in.id().id()) + " (ids 0.." +
                                                  std::to_string(std::min(per_team, 16) - 1) + ")");
  const uint8_t id = static_cast<uint8_t>(in.id().id());
  const std::string who = at + " (" + (team == idl::TEAM_BLUE ? "blue " : "yellow ") + std::to_string(id) + ")";
  if (in.by_force())
    return p->AddUnsupported(kUnsupportedByForce, who +
                                                      ".by_force: turf cannot drive a robot to a target; "
                                                      "it was not moved (send by_force false to teleport it)");
  const idl::RobotState* now = FindRobot(ctx.world, team, id);
  if (!in.has_present() && now == nullptr)
    return p->Add(DecodeError::kMissingRequired, who + ": present is absent and the robot's state is not known");
  const bool on_field = in.has_present() ? in.present() : now->on_field();
  const bool was_on = now != nullptr && now->on_field();
  const double cur[3] = {was_on ? now->position().x() : 0.0, was_on ? now->position().y() : 0.0,
                         was_on ? now->yaw() : 0.0};
  const double zero = 0.0;
  double x = 0.0, y = 0.0, yaw = 0.0;
  // Off-field robots are checked too: a NaN anywhere refuses the command.
  bool ok = Coordinate(in.has_x(), in.x(), who + ".x", was_on || !on_field ? &cur[0] : nullptr, p, &x);
  ok = Coordinate(in.has_y(), in.y(), who + ".y", was_on || !on_field ? &cur[1] : nullptr, p, &y) && ok;
  ok =
      Coordinate(in.has_orientation(), in.orientation(), who + ".orientation", was_on ? &cur[2] : &zero, p, &yaw) && ok;
  ok = Velocity(in.v_x(), in.v_y(), 0.0f, kMaxTeleportSpeed, who + ".v", p) && ok;
  ok = p->Check(in.v_angular(), -kMaxCommandAngularSpeed, kMaxCommandAngularSpeed, who, ".v_angular") && ok;
  if (!ok) return;
  // The one placement check of every protocol (core/input_limits.h), on or off the field.
  RobotTeleport placement;
  placement.x = x;
  placement.y = y;
  placement.orientation = yaw;
  placement.velocity = {in.v_x(), in.v_y(), in.v_angular()};
  if (const InputProblem bad = CheckPlacementValues(placement); !bad.ok())
    return p->Add(bad.error, who + "." + bad.field + " is outside its limits");
  if (on_field) CheckInsideWalls(x, y, ctx.field != nullptr ? ctx.field->max_robot_radius() : 0.0, ctx.field, who, p);
  idl::SimControl c = Request(idl::OP_TELEPORT_ROBOT);
  c.robot().team(team);
  c.robot().id(id);
  c.robot().on_field(on_field);
  c.robot().position(V2(on_field ? x : 0.0, on_field ? y : 0.0));
  c.robot().orientation(on_field ? yaw : 0.0);
  c.robot().velocity(V3(on_field ? in.v_x() : 0.0, on_field ? in.v_y() : 0.0, on_field ? in.v_angular() : 0.0));
  out->push_back(c);
}

void ConvertSpeed(float speed, const ControlContext& ctx, Problems* p, std::vector<idl::SimControl>* out) {
  if (!p->Check(speed, 0.0, kMaxSimulationSpeed, "simulation_speed")) return;
  if (speed > 0.0f && speed < kMinSimulationSpeed)
    return p->Add(DecodeError::kOutOfRange, "simulation_speed " + std::to_string(speed) +
                                                " is neither 0 (pause) nor in [" + std::to_string(kMinSimulationSpeed) +
                                                ", " + std::to_string(kMaxSimulationSpeed) + "]");
  if (ctx.sync)
    return p->AddUnsupported(kUnsupportedSyncSpeed,
                             "simulation_speed on the sync port: sync requests step the "
                             "simulation in lockstep; use the control port to change speed");
  if (speed == 0.0f) {
    out->push_back(Request(idl::OP_PAUSE));
    return;
  }
  idl::SimControl mode = Request(idl::OP_SET_TIME_MODE);
  mode.time_mode(speed == 1.0f ? idl::TIME_REALTIME : idl::TIME_SCALED);
  mode.speed(speed);
  out->push_back(mode);
  out->push_back(Request(idl::OP_RESUME));  // speed 0 paused; any other speed runs
}

void ConvertConfig(const ws::SimulatorConfig& config, Problems* p, std::vector<idl::SimControl>* out) {
  const std::string immutable = "turf's scene is immutable at run time (it comes from the --scene file of turf-sim)";
  if (config.has_geometry()) p->AddUnsupported(kUnsupportedGeometry, "config.geometry: " + immutable);
  if (config.robot_specs_size() > 0) p->AddUnsupported(kUnsupportedRobotSpecs, "config.robot_specs: " + immutable);
  if (config.has_realism_config()) {
    std::vector<idl::RealismValue> values = RealismValues(config.realism_config(), p);
    if (!values.empty()) {
      idl::SimControl c = Request(idl::OP_SET_REALISM);
      c.realism_values(std::move(values));
      out->push_back(c);
    }
  }
  if (config.has_vision_port())
    p->AddUnsupported(kUnsupportedVisionPort,
                      "config.vision_port: the SSL-Vision bridge's port is set by its "
                      "own command line, not at run time");
}

}  // namespace

SimulatorCommandDecode ConvertSimulatorCommand(const ws::SimulatorCommand& message, const ControlContext& ctx) {
  SimulatorCommandDecode out;
  Problems p;
  if (message.has_control()) {
    const ws::SimulatorControl& control = message.control();
    bool safely = false;
    if (control.has_teleport_ball()) ConvertBall(control.teleport_ball(), ctx, &p, &out.requests, &safely);
    std::vector<idl::SimControl> robots;
    std::set<std::pair<idl::Team, uint8_t>> teleported;
    std::set<std::pair<int, uint32_t>> listed;  // each robot once (2040 teleports of one robot were 2040 states)
    for (int i = 0; i < control.teleport_robot_size(); ++i) {
      const ws::RobotId& id = control.teleport_robot(i).id();
      if (!listed.insert({static_cast<int>(id.team()), id.id()}).second) {
        p.Add(DecodeError::kDuplicateRobot, "teleport_robot[" + std::to_string(i) + "]: robot " +
                                                std::to_string(id.id()) + " of that team is teleported twice");
        break;
      }
      ConvertRobot(control.teleport_robot(i), i, ctx, &p, &robots);
    }
    for (const idl::SimControl& r : robots) teleported.insert({r.robot().team(), r.robot().id()});
    if (safely && p.ok()) ClearBallTarget(out.requests.back().ball(), ctx, teleported, &out.requests);
    out.requests.insert(out.requests.end(), robots.begin(), robots.end());
    if (control.has_simulation_speed()) ConvertSpeed(control.simulation_speed(), ctx, &p, &out.requests);
  }
  if (message.has_config()) ConvertConfig(message.config(), &p, &out.requests);
  ReportUnknownFields(message, &p.errors());
  out.error = p.error();
  out.errors = std::move(p.errors());
  if (out.error != DecodeError::kOk) out.requests.clear();
  return out;
}

SimulatorCommandDecode DecodeSimulatorCommand(const uint8_t* data, size_t size, const ControlContext& ctx) {
  return ParseThen<ws::SimulatorCommand, SimulatorCommandDecode>(
      data, size, [&](const ws::SimulatorCommand& message) { return ConvertSimulatorCommand(message, ctx); });
}

SimError RejectedBySim(const idl::SimControlReply& reply) {
  static const char* const kOps[] = {"teleport_ball", "teleport_robot", "pause",         "resume",
                                     "step",          "reset",          "set_time_mode", "set_realism"};
  const int op = static_cast<int>(reply.op());
  const int known = static_cast<int>(sizeof(kOps) / sizeof(kOps[0]));
  const std::string name = op >= 0 && op < known ? kOps[op] : "op " + std::to_string(op);
  return {kRejectedBySim, "turf-sim refused " + name + ": " + reply.reason()};
}

std::vector<uint8_t> EncodeSimulatorResponse(const std::vector<SimError>& errors) {
  ws::SimulatorResponse response;
  AppendErrors(errors, response.mutable_errors());
  std::vector<uint8_t> bytes(response.ByteSizeLong());
  response.SerializeToArray(bytes.data(), static_cast<int>(bytes.size()));
  return bytes;
}

}  // namespace turf::simproto
