#include "participants/viewer/page_request.h"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <optional>

#include "core/input_limits.h"
#include "idl/values.h"
#include "kernel/time_control.h"
#include "participants/viewer/viewer_json.h"

namespace turf::viewer {

namespace {

using idl::V3;

using nlohmann::json;

constexpr const char* kPresets[] = {"ideal", "realistic", "harsh"};

// Reads the keys of one message object; the first problem wins and sticks.
class Fields {
 public:
  explicit Fields(const json& object, PageRequest* out) : object_(object), out_(out) {}

  bool ok() const { return out_->error == PageError::kOk; }
  bool Fail(PageError error, std::string detail) {
    if (ok()) {
      out_->error = error;
      out_->detail = std::move(detail);
    }
    return false;
  }

  // Refuses any key not in `allowed`.
  bool OnlyKeys(std::initializer_list<const char*> allowed) {
    for (const auto& item : object_.items()) {
      bool known = false;
      for (const char* a : allowed) known = known || item.key() == a;
      if (!known)
        return Fail(PageError::kUnknownKey, fmt::format("'{}' does not take '{}'", out_->op, Clip(item.key())));
    }
    return ok();
  }
  bool Has(const char* key) const { return object_.contains(key); }

  // A finite number in [lo, hi]; `fallback` if absent and not required.
  double Number(const char* key, double lo, double hi, std::optional<double> fallback = std::nullopt) {
    const json* it = Field(key, fallback.has_value());
    if (it == nullptr) return fallback.value_or(0.0);
    if (!Typed(it->is_number(), key, "a number")) return 0.0;
    const double v = it->get<double>();
    if (!std::isfinite(v)) {
      Fail(PageError::kNotFinite, fmt::format("'{}' is not finite", key));
      return 0.0;
    }
    if (v < lo || v > hi) {
      Fail(PageError::kOutOfRange, fmt::format("'{}' = {} is outside [{}, {}]", key, v, lo, hi));
      return 0.0;
    }
    return v;
  }
  // A whole number in [lo, hi].
  int64_t Integer(const char* key, int64_t lo, int64_t hi, std::optional<int64_t> fallback = std::nullopt) {
    const json* it = Field(key, fallback.has_value());
    if (it == nullptr) return fallback.value_or(0);
    if (!Typed(it->is_number_integer(), key, "a whole number")) return 0;
    // Unsigned first: 2^64-1 must not wrap to -1.
    const bool in_range = it->is_number_unsigned() ? it->get<uint64_t>() <= static_cast<uint64_t>(hi)
                                                   : it->get<int64_t>() >= lo && it->get<int64_t>() <= hi;
    if (!in_range) {
      Fail(PageError::kOutOfRange, fmt::format("'{}' is outside [{}, {}]", key, lo, hi));
      return 0;
    }
    const int64_t v = it->get<int64_t>();
    if (v < lo) Fail(PageError::kOutOfRange, fmt::format("'{}' is outside [{}, {}]", key, lo, hi));
    return v;
  }
  std::string String(const char* key) {
    const json* it = Field(key, false);
    if (it == nullptr || !Typed(it->is_string(), key, "a string")) return "";
    return it->get<std::string>();
  }
  bool Bool(const char* key) {
    const json* it = Field(key, false);
    if (it == nullptr || !Typed(it->is_boolean(), key, "true or false")) return false;
    return it->get<bool>();
  }

  // Keys and strings from the page go into logs: keep them short and printable.
  static std::string Clip(const std::string& s) {
    std::string out;
    for (char c : s.substr(0, 32)) out += (c >= 0x20 && c < 0x7f) ? c : '?';
    return s.size() > 32 ? out + "..." : out;
  }

 private:
  // The field `key`, or null when the message has none (a kMissingField failure unless `optional`).
  const json* Field(const char* key, bool optional) {
    const auto it = object_.find(key);
    if (it != object_.end()) return &*it;
    if (!optional) Fail(PageError::kMissingField, fmt::format("'{}' needs '{}'", out_->op, key));
    return nullptr;
  }
  // `ok`, failing kWrongType ("'key' must be <what>") when not.
  bool Typed(bool ok, const char* key, const char* what) {
    if (!ok) Fail(PageError::kWrongType, fmt::format("'{}' must be {}", key, what));
    return ok;
  }

  const json& object_;
  PageRequest* out_;
};

// Half extents of the walled area for a body of radius r (turf-sim's rule).
struct Bounds {
  double x, y;
};
Bounds Inside(const idl::SslField& f, double r) {
  return {f.field_length() / 2 + f.boundary_width_goal_line() - r, f.field_width() / 2 + f.boundary_width() - r};
}

// Legged scenes: where a ball or a robot's root may go (half extents, m).
Bounds LeggedArea(const idl::LeggedSceneInfo& s) {
  if (!s.has_field()) return {kLeggedArea, kLeggedArea};
  return {s.field_length() / 2 + kLeggedMargin, s.field_width() / 2 + kLeggedMargin};
}

// Where the ball may go in the scene turf-sim runs; fails with kNoField if
// there is no ball to place (no scene yet, or a legged scene without a field).
struct BallArea {
  Bounds half;         // |x|, |y| at most these
  double radius;       // the ball's: its centre rests this high
  std::string beyond;  // what a position past `half` is, for the page
};
std::optional<BallArea> FindBallArea(Fields& in, const PageScene& scene) {
  if (scene.legged) {
    const idl::LeggedSceneInfo& s = *scene.legged;
    if (s.has_field())
      return BallArea{LeggedArea(s), s.ball_radius(), fmt::format("more than {} m off the field", kLeggedMargin)};
    in.Fail(PageError::kNoField, fmt::format("legged scene '{}' has no field and no ball", Fields::Clip(s.name())));
    return std::nullopt;
  }
  if (scene.ssl)
    return BallArea{Inside(*scene.ssl, scene.ssl->ball_radius()), scene.ssl->ball_radius(), "outside the walls"};
  in.Fail(PageError::kNoField, "the field is not known yet");
  return std::nullopt;
}

// Checks the ball's position and velocity and makes the teleport.
void PlaceBall(Fields& in, const BallArea& area, const double p[3], const double v[3], double max_speed,
               PageRequest* out) {
  if (std::abs(p[0]) > area.half.x || std::abs(p[1]) > area.half.y || p[2] < 0 || p[2] > kMaxTeleportHeight) {
    in.Fail(PageError::kOutsideField,
            fmt::format("ball at ({:.3f}, {:.3f}, {:.3f}) is {}", p[0], p[1], p[2], area.beyond));
    return;
  }
  if (std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) > max_speed) {
    in.Fail(PageError::kOutOfRange, fmt::format("ball speed is above {} m/s", max_speed));
    return;
  }
  out->control.op(idl::OP_TELEPORT_BALL);
  out->control.ball().position(V3(p[0], p[1], std::max(p[2], area.radius)));
  out->control.ball().velocity(V3(v[0], v[1], v[2]));
  // On the ground and moving along it: spinning to match, so it rolls (SSL;
  // legged scenes ignore this).
  out->control.ball().roll(p[2] <= area.radius && v[2] == 0.0);
}

void TeleportBall(Fields& in, const PageScene& scene, PageRequest* out) {
  if (!in.OnlyKeys({"op", "x", "y", "z", "vx", "vy", "vz"})) return;
  const double big = 1e3;  // numbers past any field: out of range before the wall check
  const double p[3] = {in.Number("x", -big, big), in.Number("y", -big, big), in.Number("z", -big, big, 0.0)};
  const double v[3] = {in.Number("vx", -kMaxTeleportSpeed, kMaxTeleportSpeed, 0.0),
                       in.Number("vy", -kMaxTeleportSpeed, kMaxTeleportSpeed, 0.0),
                       in.Number("vz", -kMaxTeleportSpeed, kMaxTeleportSpeed, 0.0)};
  if (!in.ok()) return;
  if (const auto area = FindBallArea(in, scene)) PlaceBall(in, *area, p, v, kMaxTeleportSpeed, out);
}

// A throw: the ball where it lies, on the ground, with the page's velocity.
void ThrowBall(Fields& in, const PageScene& scene, PageRequest* out) {
  if (!in.OnlyKeys({"op", "x", "y", "vx", "vy"})) return;
  const double big = 1e3;
  const double p[3] = {in.Number("x", -big, big), in.Number("y", -big, big), 0.0};
  const double v[3] = {in.Number("vx", -kMaxThrowSpeed, kMaxThrowSpeed),
                       in.Number("vy", -kMaxThrowSpeed, kMaxThrowSpeed), 0.0};
  if (!in.ok()) return;
  if (const auto area = FindBallArea(in, scene)) PlaceBall(in, *area, p, v, kMaxThrowSpeed, out);
}

void TeleportRobot(Fields& in, const idl::SslField* field, PageRequest* out) {
  const bool on_field = in.Bool("on_field");
  if (!in.ok()) return;
  if (!(on_field ? in.OnlyKeys({"op", "team", "id", "on_field", "x", "y", "yaw"})
                 : in.OnlyKeys({"op", "team", "id", "on_field"})))
    return;
  const std::string team = in.String("team");
  const int64_t id = in.Integer("id", 0, 255);
  if (!in.ok()) return;
  if (team != "blue" && team != "yellow") {
    in.Fail(PageError::kUnknownTeam, fmt::format("team '{}' is not blue or yellow", Fields::Clip(team)));
    return;
  }
  const double big = 1e3;
  const double x = on_field ? in.Number("x", -big, big) : 0.0;
  const double y = on_field ? in.Number("y", -big, big) : 0.0;
  const double yaw = on_field ? in.Number("yaw", -kMaxYaw, kMaxYaw) : 0.0;
  if (!in.ok()) return;
  if (!field) {
    in.Fail(PageError::kNoField, "the field is not known yet");
    return;
  }
  if (id >= field->robots_per_team()) {
    in.Fail(PageError::kUnknownRobot, fmt::format("{} robot {} does not exist (ids 0..{})", team, id,
                                                  static_cast<int>(field->robots_per_team()) - 1));
    return;
  }
  const Bounds b = Inside(*field, field->max_robot_radius());
  if (on_field && (std::abs(x) > b.x || std::abs(y) > b.y)) {
    in.Fail(PageError::kOutsideField, fmt::format("robot at ({:.3f}, {:.3f}) is outside the walls", x, y));
    return;
  }
  idl::RobotTeleport& r = out->control.robot();
  out->control.op(idl::OP_TELEPORT_ROBOT);
  r.team(team == "blue" ? idl::TEAM_BLUE : idl::TEAM_YELLOW);
  r.id(static_cast<uint8_t>(id));
  r.on_field(on_field);
  r.position().x(x);
  r.position().y(y);
  r.orientation(std::remainder(yaw, 2 * M_PI));
  r.velocity(V3(0, 0, 0));
}

void TeleportLeggedRobot(Fields& in, const idl::LeggedSceneInfo& scene, PageRequest* out) {
  if (!in.OnlyKeys({"op", "robot", "x", "y", "z", "qw", "qx", "qy", "qz"})) return;
  const std::string name = in.String("robot");
  const double big = 1e3;
  const double x = in.Number("x", -big, big);
  const double y = in.Number("y", -big, big);
  const double z = in.Number("z", 0.0, kMaxTeleportHeight);
  double q[4] = {in.Number("qw", -2, 2), in.Number("qx", -2, 2), in.Number("qy", -2, 2), in.Number("qz", -2, 2)};
  if (!in.ok()) return;
  const auto& robots = scene.robots();
  if (std::none_of(robots.begin(), robots.end(), [&](const idl::RobotDescription& r) { return r.robot() == name; })) {
    in.Fail(PageError::kUnknownRobot, fmt::format("no robot '{}' in this scene", Fields::Clip(name)));
    return;
  }
  const Bounds b = LeggedArea(scene);
  if (std::abs(x) > b.x || std::abs(y) > b.y) {
    in.Fail(PageError::kOutsideField, fmt::format("robot at ({:.3f}, {:.3f}) is outside the area", x, y));
    return;
  }
  const double norm = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  if (norm < 0.5 || norm > 1.5) {
    in.Fail(PageError::kOutOfRange, fmt::format("orientation quaternion has norm {:.3f}, not about 1", norm));
    return;
  }
  idl::LeggedTeleport& t = out->control.legged();
  out->control.op(idl::OP_TELEPORT_ROBOT);
  t.robot(name);
  t.position(V3(x, y, z));
  t.orientation().w(q[0] / norm);
  t.orientation().x(q[1] / norm);
  t.orientation().y(q[2] / norm);
  t.orientation().z(q[3] / norm);
  t.reset_joints(false);
}

void Step(Fields& in, PageRequest* out) {
  if (!in.OnlyKeys({"op", "count"})) return;
  const int64_t count = in.Integer("count", 1, kMaxStepCount, 1);
  if (!in.ok()) return;
  out->control.op(idl::OP_STEP);
  out->control.step_count(static_cast<uint32_t>(count));
}

void TimeMode(Fields& in, PageRequest* out) {
  if (!in.OnlyKeys({"op", "mode", "speed"})) return;
  const std::string mode = in.String("mode");
  if (!in.ok()) return;
  const std::optional<idl::TimeMode> known = EnumFromName<idl::TimeMode>(mode, kPageTimeModes);
  if (!known) {
    in.Fail(PageError::kUnknownMode,
            fmt::format("time mode '{}' is not {}", Fields::Clip(mode), fmt::join(kPageTimeModes, ", ")));
    return;
  }
  const idl::TimeMode m = *known;
  double speed = 1.0;
  if (m == idl::TIME_SCALED) {
    speed = in.Number("speed", kMinTimeSpeed, kMaxSpeed);
  } else if (in.Has("speed")) {
    in.Fail(PageError::kUnknownKey, fmt::format("time mode '{}' takes no 'speed'", mode));
  }
  if (!in.ok()) return;
  out->control.op(idl::OP_SET_TIME_MODE);
  out->control.time_mode(m);
  out->control.speed(speed);
}

void Realism(Fields& in, PageRequest* out) {
  if (!in.OnlyKeys({"op", "preset"})) return;
  const std::string preset = in.String("preset");
  if (!in.ok()) return;
  for (const char* p : kPresets) {
    if (preset != p) continue;
    out->control.op(idl::OP_SET_REALISM);
    out->control.realism_preset(preset);
    return;
  }
  in.Fail(PageError::kUnknownPreset,
          fmt::format("realism preset '{}' is not ideal, realistic or harsh", Fields::Clip(preset)));
}

}  // namespace

PageRequest ParsePageRequest(std::string_view text, const std::optional<idl::SslField>& field) {
  return ParsePageRequest(text, PageScene{field ? &*field : nullptr, nullptr});
}

PageRequest ParsePageRequest(std::string_view text, const PageScene& scene) {
  PageRequest out;
  if (text.size() > kMaxPageMessage) {
    out.error = PageError::kTooLarge;
    out.detail = fmt::format("{} bytes (at most {})", text.size(), kMaxPageMessage);
    return out;
  }
  // No exceptions: a parse error gives a discarded value.
  const json message = json::parse(text.begin(), text.end(), nullptr, /*allow_exceptions=*/false);
  if (message.is_discarded()) {
    out.error = PageError::kNotJson;
    out.detail = "not valid JSON";
    return out;
  }
  if (!message.is_object()) {
    out.error = PageError::kNotObject;
    out.detail = "a message must be a JSON object";
    return out;
  }
  const auto op = message.find("op");
  if (op == message.end() || !op->is_string()) {
    out.error = PageError::kUnknownOp;
    out.detail = "'op' must be a string";
    return out;
  }
  out.op = Fields::Clip(op->get<std::string>());
  Fields in(message, &out);
  const std::string& name = op->get_ref<const std::string&>();
  if (name == "teleport_ball") {
    TeleportBall(in, scene, &out);
  } else if (name == "throw_ball") {
    ThrowBall(in, scene, &out);
  } else if (name == "teleport_robot" && scene.legged) {
    TeleportLeggedRobot(in, *scene.legged, &out);
  } else if (name == "teleport_robot") {
    TeleportRobot(in, scene.ssl, &out);
  } else if (name == "step") {
    Step(in, &out);
  } else if (name == "time_mode") {
    TimeMode(in, &out);
  } else if (name == "realism") {
    Realism(in, &out);
  } else if (name == "pause" || name == "resume" || name == "reset") {
    if (in.OnlyKeys({"op"}))
      out.control.op(name == "pause" ? idl::OP_PAUSE : name == "resume" ? idl::OP_RESUME : idl::OP_RESET);
  } else {
    in.Fail(PageError::kUnknownOp, fmt::format("unknown op '{}'", out.op));
  }
  return out;
}

}  // namespace turf::viewer
