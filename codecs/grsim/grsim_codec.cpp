#include "codecs/grsim/grsim_codec.h"

#include <climits>
#include <cmath>
#include <initializer_list>
#include <set>
#include <utility>

#include "codecs/proto/grsim.pb.h"
#include "core/input_limits.h"

namespace turf::grsim {

namespace {

namespace wire = turf::wire::grsim;

constexpr uint32_t kMaxGrsimId = 15;
constexpr size_t kMaxUdpPayload = 65507;
constexpr double kDegToRad = M_PI / 180.0;
// turf-sim refuses chip angles of 90 degrees and more; a vertical grSim chip
// (kickspeedx 0, kickspeedz > 0) is launched at this angle instead.
constexpr double kSteepestChip = 89.0 * kDegToRad;

// Each converter answers kOk, or the error with the culprit's name in *field.
using Named = std::initializer_list<std::pair<const char*, double>>;

GrsimError CheckFinite(Named values, std::string* field) {
  for (const auto& [name, value] : values) {
    if (!std::isfinite(value)) {
      *field = name;
      return GrsimError::kNotFinite;
    }
  }
  return GrsimError::kOk;
}

bool KnownId(uint32_t id, const GrsimCodecConfig& config) {
  return id <= kMaxGrsimId && static_cast<int64_t>(id) < config.robots_per_team;
}

GrsimError ConvertKick(const wire::grSim_Robot_Command& in, const GrsimCodecConfig& config, idl::SslRobotCommand* out,
                       std::string* field) {
  const double x = in.kickspeedx();
  const double z = in.kickspeedz();
  if (x < 0) *field = "kickspeedx";
  if (z < 0) *field = "kickspeedz";
  if (x < 0 || z < 0) return GrsimError::kOutOfRange;
  if (z > 0) {
    double speed = std::hypot(x, z);
    if (speed > kMaxKickSpeed) {
      *field = "kickspeedz";
      return GrsimError::kOutOfRange;
    }
    if (config.max_chip_kick_speed > 0) speed = std::min(speed, config.max_chip_kick_speed);
    out->kick(idl::KICK_CHIP);
    out->kick_speed(speed);
    out->chip_angle(std::min(std::atan2(z, x), kSteepestChip));
  } else if (x > 0) {
    if (x > kMaxKickSpeed) {
      *field = "kickspeedx";
      return GrsimError::kOutOfRange;
    }
    out->kick(idl::KICK_FLAT);
    out->kick_speed(config.max_flat_kick_speed > 0 ? std::min(x, config.max_flat_kick_speed) : x);
  }
  return GrsimError::kOk;
}

GrsimError ConvertCommand(const wire::grSim_Robot_Command& in, idl::Team team, const GrsimCodecConfig& config,
                          idl::SslRobotCommand* out, std::string* field) {
  const bool has_wheel[4] = {in.has_wheel1(), in.has_wheel2(), in.has_wheel3(), in.has_wheel4()};
  const double wheel[4] = {in.wheel1(), in.wheel2(), in.wheel3(), in.wheel4()};
  static const char* const kWheelName[4] = {"wheel1", "wheel2", "wheel3", "wheel4"};
  GrsimError e = CheckFinite({{"kickspeedx", in.kickspeedx()},
                              {"kickspeedz", in.kickspeedz()},
                              {"veltangent", in.veltangent()},
                              {"velnormal", in.velnormal()},
                              {"velangular", in.velangular()},
                              {"wheel1", wheel[0]},
                              {"wheel2", wheel[1]},
                              {"wheel3", wheel[2]},
                              {"wheel4", wheel[3]}},
                             field);
  if (e != GrsimError::kOk) return e;
  if (!KnownId(in.id(), config)) {
    *field = "id";
    return GrsimError::kUnknownRobot;
  }
  if (std::hypot(double{in.veltangent()}, double{in.velnormal()}) > kMaxCommandSpeed) {
    *field = "veltangent";
    return GrsimError::kOutOfRange;
  }
  if (std::abs(in.velangular()) > kMaxCommandAngularSpeed) {
    *field = "velangular";
    return GrsimError::kOutOfRange;
  }
  double rim[4];
  for (int i = 0; i < 4; ++i) {
    rim[i] = wheel[i] * config.wheel_radius;
    if (std::abs(rim[i]) > kMaxCommandSpeed) {
      *field = kWheelName[i];
      return GrsimError::kOutOfRange;
    }
    if (in.wheelsspeed() && !has_wheel[i]) {
      *field = kWheelName[i];
      return GrsimError::kMissingRequired;
    }
  }
  out->team(team);
  out->id(static_cast<uint8_t>(in.id()));
  if (in.wheelsspeed()) {
    out->move(idl::MOVE_WHEEL_VELOCITY);
    for (size_t i = 0; i < 4; ++i) out->wheel_velocity()[i] = rim[static_cast<size_t>(config.wheel_source[i]) % 4];
  } else {
    out->move(idl::MOVE_LOCAL_VELOCITY);
    out->velocity().x(in.veltangent());
    out->velocity().y(in.velnormal());
    out->velocity().z(in.velangular());
  }
  out->dribbler_speed(in.spinner() ? config.dribbler_rpm : 0.0);
  return ConvertKick(in, config, out, field);
}

// Inside the walls less `radius` (true while the walls are unknown).
bool InsideWalls(double x, double y, double radius, const GrsimCodecConfig& config) {
  if (config.wall_x <= 0 || config.wall_y <= 0) return true;
  return std::abs(x) <= config.wall_x - radius && std::abs(y) <= config.wall_y - radius;
}

GrsimError ConvertBall(const wire::grSim_BallReplacement& in, const GrsimCodecConfig& config, idl::SimControl* out,
                       std::string* field) {
  GrsimError e = CheckFinite({{"x", in.x()}, {"y", in.y()}, {"vx", in.vx()}, {"vy", in.vy()}}, field);
  if (e != GrsimError::kOk) return e;
  if (!InsideWalls(in.x(), in.y(), config.ball_radius, config)) {
    *field = "x";
    return GrsimError::kOutsideField;
  }
  if (std::hypot(in.vx(), in.vy()) > kMaxTeleportSpeed) {
    *field = "vx";
    return GrsimError::kOutOfRange;
  }
  out->op(idl::OP_TELEPORT_BALL);
  out->ball().position().x(in.x());
  out->ball().position().y(in.y());
  out->ball().velocity().x(in.vx());
  out->ball().velocity().y(in.vy());
  return GrsimError::kOk;
}

GrsimError ConvertRobot(const wire::grSim_RobotReplacement& in, const GrsimCodecConfig& config, idl::SimControl* out,
                        std::string* field) {
  // Every field, whatever turnon says: a robot taken off the field with x = 1e308 is a bad datagram too.
  RobotTeleport placement;
  placement.x = in.x();
  placement.y = in.y();
  placement.orientation = in.dir() * kDegToRad;
  if (const InputProblem p = CheckPlacementValues(placement); !p.ok()) {
    *field = std::string(p.field) == "orientation" ? "dir" : p.field;
    return p.error;
  }
  if (!KnownId(in.id(), config)) {
    *field = "id";
    return GrsimError::kUnknownRobot;
  }
  const bool on_field = in.has_turnon() ? in.turnon() : true;
  if (on_field && !InsideWalls(in.x(), in.y(), config.robot_radius, config)) {
    *field = "x";
    return GrsimError::kOutsideField;
  }
  out->op(idl::OP_TELEPORT_ROBOT);
  idl::RobotTeleport& r = out->robot();
  r.team(in.yellowteam() ? idl::TEAM_YELLOW : idl::TEAM_BLUE);
  r.id(static_cast<uint8_t>(in.id()));
  r.on_field(on_field);
  r.position().x(in.x());
  r.position().y(in.y());
  r.orientation(std::remainder(in.dir() * kDegToRad, 2 * M_PI));  // degrees -> (-pi, pi]
  return GrsimError::kOk;
}

GrsimDecodeResult Fail(GrsimError error, std::string detail) {
  GrsimDecodeResult r;
  r.error = error;
  r.detail = std::move(detail);
  return r;
}

std::string Indexed(const char* list, int i, const std::string& field) {
  return std::string(list) + "[" + std::to_string(i) + "]." + field;
}

}  // namespace

std::string CheckConfig(const GrsimCodecConfig& c) {
  if (!(std::isfinite(c.wheel_radius) && c.wheel_radius > 0 && c.wheel_radius < 1))
    return "wheel radius must be in (0, 1) m";
  bool seen[4] = {false, false, false, false};
  for (int source : c.wheel_source) {
    if (source < 0 || source > 3 || seen[source]) return "the wheel mapping must name each grSim wheel 1..4 once";
    seen[source] = true;
  }
  if (c.robots_per_team < 0 || c.robots_per_team > static_cast<int>(kMaxGrsimId) + 1)
    return "robots per team must be 0..16";
  if (!(std::isfinite(c.dribbler_rpm) && c.dribbler_rpm >= 0 && c.dribbler_rpm <= kMaxDribblerSpeed))
    return "dribbler speed must be in [0, " + std::to_string(static_cast<int>(kMaxDribblerSpeed)) + "] rpm";
  if (c.max_datagram_size < 1 || c.max_datagram_size > kMaxUdpPayload)
    return "max datagram size must be 1.." + std::to_string(kMaxUdpPayload) + " bytes";
  if (!(std::isfinite(c.max_flat_kick_speed) && c.max_flat_kick_speed >= 0 && std::isfinite(c.max_chip_kick_speed) &&
        c.max_chip_kick_speed >= 0))
    return "kick speed limits must be >= 0 (0: none)";
  for (double v : {c.wall_x, c.wall_y, c.ball_radius, c.robot_radius})
    if (!(std::isfinite(v) && v >= 0 && v <= 1000)) return "walls and radii must be in [0, 1000] m (0: unknown)";
  return "";
}

GrsimDecodeResult Decode(const uint8_t* bytes, size_t size, const GrsimCodecConfig& config) {
  if (size == 0) return Fail(GrsimError::kEmpty, "0 bytes");
  if (size > config.max_datagram_size || size > INT_MAX)
    return Fail(GrsimError::kOversized,
                std::to_string(size) + " bytes, more than " + std::to_string(config.max_datagram_size));
  wire::grSim_Packet packet;
  // Partial parsing tells a packet that lacks a required field from one that is not a packet.
  if (!packet.ParsePartialFromArray(bytes, static_cast<int>(size)))
    return Fail(GrsimError::kMalformed, std::to_string(size) + " bytes are not a grSim_Packet");
  if (!packet.IsInitialized()) return Fail(GrsimError::kMissingRequired, packet.InitializationErrorString());

  GrsimDecodeResult result;
  GrsimRequests& out = result.requests;
  std::string field;
  if (packet.has_commands()) {
    const wire::grSim_Commands& commands = packet.commands();
    if (!std::isfinite(commands.timestamp())) return Fail(GrsimError::kNotFinite, "commands.timestamp");
    const idl::Team team = commands.isteamyellow() ? idl::TEAM_YELLOW : idl::TEAM_BLUE;
    out.command_team = team;
    out.commands.resize(static_cast<size_t>(commands.robot_commands_size()));
    for (int i = 0; i < commands.robot_commands_size(); ++i) {
      const GrsimError e = ConvertCommand(commands.robot_commands(i), team, config, &out.commands[i], &field);
      if (e != GrsimError::kOk) return Fail(e, Indexed("robot_commands", i, field));
    }
  }
  if (packet.has_replacement()) {
    const wire::grSim_Replacement& replacement = packet.replacement();
    std::set<std::pair<bool, uint32_t>> replaced;  // each robot once (490 replacements a packet: as many states)
    for (int i = 0; i < replacement.robots_size(); ++i) {
      idl::SimControl control;
      const GrsimError e = ConvertRobot(replacement.robots(i), config, &control, &field);
      if (e != GrsimError::kOk) return Fail(e, Indexed("replacement.robots", i, field));
      if (!replaced.insert({replacement.robots(i).yellowteam(), replacement.robots(i).id()}).second)
        return Fail(GrsimError::kDuplicateRobot, Indexed("replacement.robots", i, "id"));
      out.controls.push_back(std::move(control));
    }
    if (replacement.has_ball()) {
      idl::SimControl control;
      const GrsimError e = ConvertBall(replacement.ball(), config, &control, &field);
      if (e != GrsimError::kOk) return Fail(e, "replacement.ball." + field);
      out.controls.push_back(std::move(control));
    }
  }
  return result;
}

}  // namespace turf::grsim
