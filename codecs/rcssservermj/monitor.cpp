#include "codecs/rcssservermj/monitor.h"

#include <fmt/format.h>

#include <cmath>

#include "codecs/simspark/sexpr.h"
#include "core/legged/placement_limits.h"

namespace turf::rcssservermj {

namespace {

using simspark::SExpr;

constexpr double kMaxNumber = 1e6;  // any number of a command: a yaw in degrees, a quaternion's component
constexpr double kRad = M_PI / 180.0;

// The n numbers after the head of `e` (a list like `(pos 1 2 3)`).
turf::Error Numbers(const SExpr* e, size_t n, double* out) {
  if (e == nullptr || e->items.size() != n + 1) return turf::Error::kBadArguments;
  for (size_t i = 0; i < n; ++i) {
    if (e->items[i + 1].is_list) return turf::Error::kBadArguments;
    const simspark::NumberError error = simspark::ParseDouble(e->items[i + 1].atom, &out[i]);
    if (error == simspark::NumberError::kNotFinite) return turf::Error::kNotFinite;
    if (error != simspark::NumberError::kOk) return turf::Error::kBadArguments;
    if (std::abs(out[i]) > kMaxNumber) return turf::Error::kOutOfRange;
  }
  return turf::Error::kOk;
}

// A position's x, y and z within the legged scenes' placement limit (core/legged/placement_limits.h).
turf::Error Position(const double* v) {
  for (int i = 0; i < 3; ++i)
    if (std::abs(v[i]) > kMaxLeggedPlacement) return turf::Error::kOutOfRange;
  return turf::Error::kOk;
}

std::optional<bool> SideWord(std::string_view w, bool* ok) {
  *ok = true;
  if (w == "Left" || w == "left" || w == "L" || w == "l") return true;
  if (w == "Right" || w == "right" || w == "R" || w == "r") return false;
  *ok = false;
  return std::nullopt;
}

turf::Error Agent(const SExpr& e, AgentCommand* out) {
  const SExpr* unum = e.Child("unum");
  const SExpr* team = e.Child("team");
  if (unum == nullptr || team == nullptr || unum->items.size() != 2 || team->items.size() != 2 ||
      unum->items[1].is_list || team->items[1].is_list || !simspark::ParseInt(unum->items[1].atom, &out->unum))
    return turf::Error::kBadArguments;
  const std::string& name = team->items[1].atom;
  out->team = name == "Left" ? TeamRef::kLeft : name == "Right" ? TeamRef::kRight : TeamRef::kName;
  out->team_name = name;
  double v[7];
  if (const SExpr* pos = e.Child("pos")) {
    const turf::Error error = Numbers(pos, 3, v);
    if (error != turf::Error::kOk) return error;
  } else if (const SExpr* move = e.Child("move")) {
    const turf::Error error = Numbers(move, 4, v);
    if (error != turf::Error::kOk) return error;
    out->orientation = Eigen::AngleAxisd(v[3] * kRad, Eigen::Vector3d::UnitZ());
  } else if (const SExpr* move3d = e.Child("move3d")) {
    const turf::Error error = Numbers(move3d, 7, v);
    if (error != turf::Error::kOk) return error;
    Eigen::Quaterniond q(v[3], v[4], v[5], v[6]);
    if (q.norm() < 1e-9) return turf::Error::kOutOfRange;
    out->orientation = q.normalized();
  } else {
    return turf::Error::kBadArguments;
  }
  out->position = Eigen::Vector3d(v[0], v[1], v[2]);
  return Position(v);
}

turf::Error Command(const SExpr& e, MonitorCommand* out) {
  const std::string_view head = e.Head();
  if (head == "kickOff") {
    if (e.items.size() == 1) {
      *out = KickOffCommand{};
      return turf::Error::kOk;
    }
    bool ok = false;
    const std::optional<bool> left =
        e.items.size() == 2 && !e.items[1].is_list ? SideWord(e.items[1].atom, &ok) : std::nullopt;
    if (!ok) return turf::Error::kBadArguments;
    *out = KickOffCommand{left};
    return turf::Error::kOk;
  }
  if (head == "dropBall") {
    *out = DropBallCommand{};
    return turf::Error::kOk;
  }
  if (head == "ball") {
    double v[3];
    turf::Error error = Numbers(e.Child("pos"), 3, v);
    if (error == turf::Error::kOk) error = Position(v);
    if (error != turf::Error::kOk) return error;
    *out = BallCommand{v[0], v[1]};
    return turf::Error::kOk;
  }
  if (head == "agent") {
    AgentCommand agent;
    const turf::Error error = Agent(e, &agent);
    if (error != turf::Error::kOk) return error;
    *out = agent;
    return turf::Error::kOk;
  }
  if (head == "playMode") {
    if (e.items.size() != 2 || e.items[1].is_list) return turf::Error::kBadArguments;
    *out = PlayModeCommand{e.items[1].atom};
    return turf::Error::kOk;
  }
  if (head == "killsim") {
    *out = KillSimCommand{};
    return turf::Error::kOk;
  }
  return turf::Error::kUnknownOp;
}

}  // namespace

MonitorMessage ParseMonitorMessage(std::string_view payload) {
  MonitorMessage m;
  for (const SExpr& e : simspark::ParseSExprsOrIssue(payload, &m.issues)) {
    MonitorCommand c;
    const turf::Error error = Command(e, &c);
    if (error == turf::Error::kOk) {
      m.commands.push_back(std::move(c));
    } else {
      m.issues.push_back({error, fmt::format("({} ...): {}", e.Head().substr(0, 32), turf::ErrorName(error))});
    }
  }
  return m;
}

}  // namespace turf::rcssservermj
