// The SimSpark monitor / trainer port (TCP 3200, framed as the agent port;
// shared/protocols/simspark.md, "Monitor / trainer port 3200"): trainer
// commands in, the game-state part of the monitor frames out (the scene graph
// is not written here).
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "kernel/simspark/types.h"

namespace turf::simspark {

enum class TrainerTeam { kLeft, kRight, kNone };  // wire: Left, Right, None

// (agent (unum 2) (team Left) (pos x y z)) or (... (move x y z yaw)): global field frame, m, deg.
struct MoveAgent {
  int unum = 0;
  TrainerTeam team = TrainerTeam::kNone;
  std::array<double, 3> pos{};
  std::optional<double> yaw_deg;  // move: torso yaw (raw: -90 faces +x)
};
// (ball (pos x y z) (vel x y z)): at least one of the two.
struct SetBall {
  std::optional<std::array<double, 3>> pos;
  std::optional<std::array<double, 3>> vel;
};
struct SetPlayModeCmd {  // (playMode PlayOn)
  PlayMode mode = PlayMode::kBeforeKickOff;
};
struct KickOffCmd {  // (kickOff Left|Right|None); None = coin toss
  TrainerTeam team = TrainerTeam::kNone;
};
struct DropBallCmd {};       // (dropBall)
struct RequestFullState {};  // (reqfullstate)
struct SetGameTime {         // (time T), T >= 0
  double time = 0;
};
struct SetScoreCmd {  // (score (left N) (right N)), 0..999, at least one
  std::optional<int> left, right;
};
struct KillAgent {  // (kill (unum N) (team T))
  int unum = 0;
  TrainerTeam team = TrainerTeam::kNone;
};
struct SelectAgent {  // (select (unum N) (team T))
  int unum = 0;
  TrainerTeam team = TrainerTeam::kNone;
};
struct ReposAgent {  // (repos (unum N) (team T))
  int unum = 0;
  TrainerTeam team = TrainerTeam::kNone;
};
struct KillSim {};        // (killsim)
struct AgentStateCmd {};  // (agent ... (battery B)) / (temperature T): accepted, no effect on a Nao
// (turfResetTeam Left|Right): turf's own command, not rcssserver3d's (whose trainer cannot free a team name): the
// side's players are disconnected and its team name is freed, so that another team can claim the side (say, after
// a throwaway agent claimed the real team's name or side).
struct ResetTeamCmd {
  TrainerTeam team = TrainerTeam::kLeft;  // Left or Right
};

using TrainerCommand =
    std::variant<MoveAgent, SetBall, SetPlayModeCmd, KickOffCmd, DropBallCmd, RequestFullState, SetGameTime,
                 SetScoreCmd, KillAgent, SelectAgent, ReposAgent, KillSim, AgentStateCmd, ResetTeamCmd>;

// The ranges every decoded value is in (a value outside is refused, "out_of_range"). Positions: x and y within
// core/legged/placement_limits.h's kMaxLeggedPlacement (turf-sim's own limit), height (z) 0..kMaxTeleportHeight; a
// move's yaw within kMaxPlacementOrientation (as radians); the ball's speed at most kMaxTeleportSpeed. Game time
// 0..kMaxTrainerTime, score 0..999, unum 0..99, battery 0..100 (%), temperature -273.15..1000 (deg C).
inline constexpr double kMaxTrainerTime = 86400.0;  // s: no match is near a day long

// error: "parse" (not S-expressions: nothing applied), "unknown_command", "bad_arguments" (wrong form, unknown
// team, play mode or agent part), "not_finite", "out_of_range" (a value outside the ranges above).
struct TrainerIssue {
  std::string error;
  std::string detail;
};

// Commands in message order. A command with any bad part is dropped whole with
// one issue; the others apply. (getAck) is accepted and yields nothing. One
// agent command may yield several commands (e.g. pos and battery).
struct TrainerMessage {
  std::vector<TrainerCommand> commands;
  std::vector<TrainerIssue> issues;
};

TrainerMessage ParseTrainerMessage(std::string_view payload);

// Whether a command ends, restarts or rewrites the match: only an operator may send it (session.h, TrainerRole).
// They are (killsim) (ends the run), (kill ...) (ends a player's connection), (kickOff ...) and the play modes
// BeforeKickOff, KickOff_Left, KickOff_Right and GameOver (restart or end play), (time ...) (rewinds the clock or
// ends a half or the match), (score ...) (rewrites the result) and (turfResetTeam ...). The rest (moving the ball
// and agents, (dropBall), the other play modes, (select), (repos), (reqfullstate), agent state) is open to every
// trainer: it is what training tools do.
bool IsMatchControl(const TrainerCommand& command);
const char* TrainerCommandName(const TrainerCommand& command);  // its wire name: "killsim", "playMode", ...

struct MonitorGameState {
  double time = 0;  // game time s
  int half = 1;
  int score_left = 0, score_right = 0;
  PlayMode play_mode = PlayMode::kBeforeKickOff;
  std::string team_left, team_right;  // empty until known
};

// Numbers on the monitor port are written as a C++ stream writes a double by
// default (6 significant digits, no trailing zeros: "30", "0.042", "12.34").
std::string FormatMonitorNumber(double v);

// The environment predicates of the first (full) frame, ending with
// (play_modes <21 names in index order>). The caller puts them, followed by
// FormatMonitorGame(state, nullptr), inside the frame's first list:
// `(<env><game>)(RSG 0 1)(<scene graph>)`.
std::string FormatMonitorEnvironment();

// (time T) always; (team_left N) (team_right N) when known and new; (half) (score_left) (score_right)
// (play_mode <index>) when changed from `previous` or previous == nullptr.
std::string FormatMonitorGame(const MonitorGameState& now, const MonitorGameState* previous);

}  // namespace turf::simspark
