#include "codecs/simspark/trainer.h"

#include <cmath>
#include <cstdio>
#include <iterator>

#include "codecs/simspark/sexpr.h"
#include "core/input_limits.h"
#include "core/legged/placement_limits.h"

namespace turf::simspark {

namespace {

constexpr int kMaxUnum = 99;
constexpr int kMaxScore = 999;
constexpr double kMaxBattery = 100.0;        // %
constexpr double kMinTemperature = -273.15;  // deg C: absolute zero
constexpr double kMaxTemperature = 1000.0;
constexpr double kRadPerDeg = M_PI / 180.0;

std::string Name(std::string_view name) { return std::string(name.substr(0, 32)); }

// A refused command: the issue to report.
struct Refusal {
  const char* error;
  std::string detail;
};
using Result = std::optional<Refusal>;  // nullopt = fine

Result Bad(std::string detail) { return Refusal{"bad_arguments", std::move(detail)}; }

// `(head a1 ... an)` with n atoms.
bool AtomsOf(const SExpr& e, size_t n) {
  if (e.items.size() != n + 1) return false;
  for (size_t i = 1; i <= n; ++i)
    if (e.items[i].is_list) return false;
  return true;
}

// `(head x1 ... xn)`: n finite numbers.
Result Numbers(const SExpr& e, size_t n, double* out) {
  const std::string head(e.Head());
  if (!AtomsOf(e, n)) return Bad(head + ": expected " + std::to_string(n) + " numbers");
  for (size_t i = 0; i < n; ++i) {
    const NumberError error = ParseDouble(e.items[i + 1].atom, &out[i]);
    if (error == NumberError::kBad) return Bad(head + ": not a number");
    if (error == NumberError::kNotFinite) return Refusal{"not_finite", head + ": nan or inf"};
  }
  return std::nullopt;
}

Result Vector3(const SExpr& e, std::array<double, 3>* out) { return Numbers(e, 3, out->data()); }

Result Integer(const SExpr& e, int lo, int hi, int* out) {
  const std::string head(e.Head());
  if (!AtomsOf(e, 1) || !ParseInt(e.items[1].atom, out)) return Bad(head + ": expected an integer");
  if (*out < lo || *out > hi)
    return Refusal{"out_of_range",
                   head + " " + std::to_string(*out) + " outside " + std::to_string(lo) + ".." + std::to_string(hi)};
  return std::nullopt;
}

// Every decoded number's range check (the integers': Integer above).
Result InRange(const std::string& what, double v, double lo, double hi) {
  if (v >= lo && v <= hi) return std::nullopt;
  return Refusal{"out_of_range", what + " " + FormatMonitorNumber(v) + " outside " + FormatMonitorNumber(lo) + ".." +
                                     FormatMonitorNumber(hi)};
}

// Where the trainer puts an agent's torso or the ball (field frame): the placement values every protocol's
// teleports are checked with (core/input_limits.h: x, y and the yaw), x and y within turf-sim's limit of a legged
// placement, and a height from the ground up.
Result CheckPosition(const std::string& what, const std::array<double, 3>& pos, double yaw_deg) {
  RobotTeleport placement;
  placement.x = pos[0];
  placement.y = pos[1];
  placement.orientation = yaw_deg * kRadPerDeg;
  if (const InputProblem p = CheckPlacementValues(placement); !p.ok())
    return Refusal{ErrorName(p.error), what + ": " + p.field + " past its limit"};
  if (Result r = InRange(what + " x", pos[0], -kMaxLeggedPlacement, kMaxLeggedPlacement)) return r;
  if (Result r = InRange(what + " y", pos[1], -kMaxLeggedPlacement, kMaxLeggedPlacement)) return r;
  return InRange(what + " z", pos[2], 0.0, kMaxTeleportHeight);
}

// The ball's velocity: a speed a teleport may give (core/input_limits.h).
Result CheckVelocity(const std::string& what, const std::array<double, 3>& v) {
  return InRange(what + " speed", std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]), 0.0, kMaxTeleportSpeed);
}

std::optional<TrainerTeam> TeamFromName(std::string_view name) {
  if (name == "Left") return TrainerTeam::kLeft;
  if (name == "Right") return TrainerTeam::kRight;
  if (name == "None") return TrainerTeam::kNone;
  return std::nullopt;
}

Result Team(const SExpr& e, TrainerTeam* out) {
  std::optional<TrainerTeam> team;
  if (AtomsOf(e, 1)) team = TeamFromName(e.items[1].atom);
  if (!team) return Bad(std::string(e.Head()) + ": expected Left, Right or None");
  *out = *team;
  return std::nullopt;
}

// Only argument-less: (dropBall), (killsim), ...
template <class Command>
Result Plain(const SExpr& e, std::vector<TrainerCommand>* out) {
  if (e.items.size() != 1) return Bad(std::string(e.Head()) + ": takes no arguments");
  out->push_back(Command{});
  return std::nullopt;
}

// (head (unum N) (team T) <other parts>): the pair is required; `other` handles the rest
// and returns false for a part it does not know.
template <class Other>
Result AgentAddress(const SExpr& e, int* unum, TrainerTeam* team, Other other) {
  bool has_unum = false, has_team = false;
  for (size_t i = 1; i < e.items.size(); ++i) {
    const SExpr& part = e.items[i];
    Result r;
    if (part.IsCall("unum")) {
      r = Integer(part, 0, kMaxUnum, unum);
      has_unum = true;
    } else if (part.IsCall("team")) {
      r = Team(part, team);
      has_team = true;
    } else if (!other(part, &r)) {
      return Bad(std::string(e.Head()) + ": unknown part " + (part.is_list ? Name(part.Head()) : Name(part.atom)));
    }
    if (r) return r;
  }
  if (!has_unum || !has_team) return Bad(std::string(e.Head()) + ": needs (unum N) and (team T)");
  return std::nullopt;
}

template <class Command>
Result Addressed(const SExpr& e, std::vector<TrainerCommand>* out) {
  Command c;
  if (Result r = AgentAddress(e, &c.unum, &c.team, [](const SExpr&, Result*) { return false; })) return r;
  out->push_back(c);
  return std::nullopt;
}

Result Agent(const SExpr& e, std::vector<TrainerCommand>* out) {
  MoveAgent move;
  bool has_move = false, has_state = false;
  auto other = [&](const SExpr& part, Result* r) {
    if (part.IsCall("pos") || part.IsCall("move")) {
      const bool turn = part.IsCall("move");
      double v[4] = {};
      *r = Numbers(part, turn ? 4 : 3, v);
      move.pos = {v[0], v[1], v[2]};
      move.yaw_deg = turn ? std::optional<double>(v[3]) : std::nullopt;
      if (!*r) *r = CheckPosition(std::string("agent ") + (turn ? "move" : "pos"), move.pos, v[3]);
      has_move = true;
      return true;
    }
    if (part.IsCall("battery") || part.IsCall("temperature")) {
      double v = 0;
      *r = Numbers(part, 1, &v);
      if (!*r && part.IsCall("battery")) *r = InRange("agent battery", v, 0.0, kMaxBattery);
      if (!*r && part.IsCall("temperature")) *r = InRange("agent temperature", v, kMinTemperature, kMaxTemperature);
      has_state = true;
      return true;
    }
    return false;
  };
  if (Result r = AgentAddress(e, &move.unum, &move.team, other)) return r;
  if (!has_move && !has_state) return Bad("agent: nothing to do (pos, move, battery or temperature)");
  if (has_move) out->push_back(move);
  if (has_state) out->push_back(AgentStateCmd{});
  return std::nullopt;
}

Result Ball(const SExpr& e, std::vector<TrainerCommand>* out) {
  SetBall ball;
  for (size_t i = 1; i < e.items.size(); ++i) {
    const SExpr& part = e.items[i];
    std::array<double, 3> v{};
    if (!part.IsCall("pos") && !part.IsCall("vel")) return Bad("ball: expected (pos x y z) and/or (vel x y z)");
    if (Result r = Vector3(part, &v)) return r;
    const bool pos = part.IsCall("pos");
    if (Result r = pos ? CheckPosition("ball pos", v, 0.0) : CheckVelocity("ball vel", v)) return r;
    (pos ? ball.pos : ball.vel) = v;
  }
  if (!ball.pos && !ball.vel) return Bad("ball: expected (pos x y z) and/or (vel x y z)");
  out->push_back(ball);
  return std::nullopt;
}

Result PlayModeCommand(const SExpr& e, std::vector<TrainerCommand>* out) {
  std::optional<PlayMode> mode;
  if (AtomsOf(e, 1)) mode = PlayModeFromName(e.items[1].atom);
  if (!mode) return Bad("playMode: expected a play-mode name");
  out->push_back(SetPlayModeCmd{*mode});
  return std::nullopt;
}

Result KickOff(const SExpr& e, std::vector<TrainerCommand>* out) {
  KickOffCmd c;
  if (Result r = Team(e, &c.team)) return r;
  out->push_back(c);
  return std::nullopt;
}

Result Time(const SExpr& e, std::vector<TrainerCommand>* out) {
  double t = 0;
  if (Result r = Numbers(e, 1, &t)) return r;
  if (Result r = InRange("time", t, 0.0, kMaxTrainerTime)) return r;
  out->push_back(SetGameTime{t});
  return std::nullopt;
}

Result Score(const SExpr& e, std::vector<TrainerCommand>* out) {
  SetScoreCmd c;
  for (size_t i = 1; i < e.items.size(); ++i) {
    const SExpr& part = e.items[i];
    if (!part.IsCall("left") && !part.IsCall("right")) return Bad("score: expected (left N) and/or (right N)");
    int n = 0;
    if (Result r = Integer(part, 0, kMaxScore, &n)) return r;
    (part.IsCall("left") ? c.left : c.right) = n;
  }
  if (!c.left && !c.right) return Bad("score: expected (left N) and/or (right N)");
  out->push_back(c);
  return std::nullopt;
}

Result ResetTeam(const SExpr& e, std::vector<TrainerCommand>* out) {
  ResetTeamCmd c;
  if (Result r = Team(e, &c.team)) return r;
  if (c.team == TrainerTeam::kNone) return Bad("turfResetTeam: expected Left or Right");
  out->push_back(c);
  return std::nullopt;
}

Result Command(const SExpr& e, std::vector<TrainerCommand>* out) {
  const std::string_view name = e.Head();
  if (name == "agent") return Agent(e, out);
  if (name == "ball") return Ball(e, out);
  if (name == "playMode") return PlayModeCommand(e, out);
  if (name == "kickOff") return KickOff(e, out);
  if (name == "dropBall") return Plain<DropBallCmd>(e, out);
  if (name == "reqfullstate") return Plain<RequestFullState>(e, out);
  if (name == "time") return Time(e, out);
  if (name == "score") return Score(e, out);
  if (name == "kill") return Addressed<KillAgent>(e, out);
  if (name == "select") return Addressed<SelectAgent>(e, out);
  if (name == "repos") return Addressed<ReposAgent>(e, out);
  if (name == "killsim") return Plain<KillSim>(e, out);
  if (name == "turfResetTeam") return ResetTeam(e, out);
  if (name == "getAck") {
    if (e.items.size() != 1) return Bad("getAck: takes no arguments");
    return std::nullopt;
  }
  return Refusal{"unknown_command", name.empty() ? "(a list without a name)" : Name(name)};
}

void AppendPredicate(std::string* out, const char* name, const std::string& value) {
  *out += '(';
  *out += name;
  *out += ' ';
  *out += value;
  *out += ')';
}

}  // namespace

TrainerMessage ParseTrainerMessage(std::string_view payload) {
  TrainerMessage message;
  const SExprParse parse = ParseSExprs(payload);
  if (parse.error != SExprError::kOk) {
    message.issues.push_back(
        {"parse", std::string(SExprErrorName(parse.error)) + " at offset " + std::to_string(parse.offset)});
    return message;
  }
  for (const SExpr& e : parse.exprs) {
    std::vector<TrainerCommand> commands;  // all of one command, or none
    if (Result r = Command(e, &commands)) {
      message.issues.push_back({r->error, std::move(r->detail)});
    } else {
      for (TrainerCommand& c : commands) message.commands.push_back(std::move(c));
    }
  }
  return message;
}

bool IsMatchControl(const TrainerCommand& command) {
  if (const auto* mode = std::get_if<SetPlayModeCmd>(&command)) {
    switch (mode->mode) {
      case PlayMode::kBeforeKickOff:
      case PlayMode::kKickOffLeft:
      case PlayMode::kKickOffRight:
      case PlayMode::kGameOver:
        return true;
      default:
        return false;
    }
  }
  return std::holds_alternative<KillSim>(command) || std::holds_alternative<KillAgent>(command) ||
         std::holds_alternative<KickOffCmd>(command) || std::holds_alternative<SetGameTime>(command) ||
         std::holds_alternative<SetScoreCmd>(command) || std::holds_alternative<ResetTeamCmd>(command);
}

const char* TrainerCommandName(const TrainerCommand& command) {
  // In the variant's order.
  static constexpr const char* kNames[] = {"agent",        "ball",    "playMode", "kickOff",      "dropBall",
                                           "reqfullstate", "time",    "score",    "kill",         "select",
                                           "repos",        "killsim", "agent",    "turfResetTeam"};
  static_assert(std::size(kNames) == std::variant_size_v<TrainerCommand>);
  return kNames[command.index()];
}

std::string FormatMonitorNumber(double v) {
  if (!std::isfinite(v)) return "0";
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%g", v);  // %g = a stream's default: 6 significant digits
  return buffer;
}

std::string FormatMonitorEnvironment() {
  std::string out =
      "(FieldLength 30)(FieldWidth 20)(FieldHeight 40)(GoalWidth 2.1)(GoalDepth 0.6)(GoalHeight 0.8)(BorderSize 0)"
      "(FreeKickDistance 2)(WaitBeforeKickOff 30)(AgentRadius 0.4)(BallRadius 0.042)(BallMass 0.026)"
      "(RuleGoalPauseTime 3)(RuleKickInPauseTime 1)(RuleHalfTime 300)(PassModeMinOppBallDist 1)"
      "(PassModeDuration 4)(play_modes";
  for (int i = 0; i < static_cast<int>(PlayMode::kCount); ++i) {
    out += ' ';
    out += PlayModeName(static_cast<PlayMode>(i));
  }
  out += ')';
  return out;
}

std::string FormatMonitorGame(const MonitorGameState& now, const MonitorGameState* previous) {
  std::string out;
  AppendPredicate(&out, "time", FormatMonitorNumber(now.time));
  if (!now.team_left.empty() && (!previous || previous->team_left != now.team_left))
    AppendPredicate(&out, "team_left", now.team_left);
  if (!now.team_right.empty() && (!previous || previous->team_right != now.team_right))
    AppendPredicate(&out, "team_right", now.team_right);
  if (!previous || previous->half != now.half) AppendPredicate(&out, "half", std::to_string(now.half));
  if (!previous || previous->score_left != now.score_left)
    AppendPredicate(&out, "score_left", std::to_string(now.score_left));
  if (!previous || previous->score_right != now.score_right)
    AppendPredicate(&out, "score_right", std::to_string(now.score_right));
  if (!previous || previous->play_mode != now.play_mode)
    AppendPredicate(&out, "play_mode", std::to_string(static_cast<int>(now.play_mode)));
  return out;
}

}  // namespace turf::simspark
