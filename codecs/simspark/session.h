// The SimSpark server's behaviour in front of a turf legged world, without
// sockets, DDS or clocks: agents connect, send effector messages and get
// perception messages; the trainer (monitor port) moves things and sets play
// modes. The participant feeds it bytes and world snapshots and carries out
// the world requests it returns (simspark_bridge.h).
//
// One cycle (0.02 s of simulated time):
//   Receive()/Trainer()   effectors and trainer commands, applied at once
//   ReadyToStep()         sync mode: every agent with a robot sent (syn)
//   TakeRequests()        robots and ball to move, joint velocities to set
//   -- the participant steps the world one cycle --
//   Advance(snapshot)     game state, then one perception per agent
//   TakeOutputs()         the perception messages (payloads, unframed)
// Facts: shared/protocols/simspark.md. As in rcssserver3d, an agent's joint
// velocities act one cycle after the perception they answer: TakeRequests()
// returns the ones asked in the previous cycle (beams and trainer moves act
// at once).
#pragma once

#include <Eigen/Geometry>
#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/rng.h"
#include "kernel/simspark/field3d.h"
#include "kernel/simspark/fouls.h"
#include "kernel/simspark/game.h"
#include "kernel/simspark/radio.h"
#include "kernel/simspark/self_collision.h"
#include "kernel/simspark/types.h"
#include "kernel/simspark/vision.h"

namespace turf::simspark {

// One robot of the world after a cycle (from turf-sim's robots/* topics).
struct RobotSnapshot {
  std::string name;
  std::vector<std::string> joint_names;
  std::vector<double> joint_positions;    // rad
  std::array<double, 3> gyro{};           // rad/s, torso frame
  std::array<double, 3> accelerometer{};  // m/s^2
  struct Foot {
    std::string name;  // lf, rf
    bool contact = false;
    std::array<double, 3> point{};
    std::array<double, 3> force{};
  };
  std::vector<Foot> feet;
  struct Link {
    std::string name;
    Eigen::Vector3d position = Eigen::Vector3d::Zero();
    Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
  };
  std::vector<Link> links;
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();  // m/s of the torso, world frame
  // s: the end of the last physics step in which the robot touched the ball (-1: never); a touch in the cycle is
  // one after the previous snapshot's time.
  double ball_touch_time = -1.0;
  const Link* FindLink(const std::string& link) const;
};

// Two robots touching in the cycle's last physics step: the mean of their contact points.
struct RobotTouch {
  std::string robot_a;
  std::string robot_b;
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
};

struct WorldSnapshot {
  double time = 0.0;  // s of simulation
  Eigen::Vector3d ball = Eigen::Vector3d::Zero();
  Eigen::Vector3d ball_velocity = Eigen::Vector3d::Zero();
  std::vector<RobotSnapshot> robots;
  std::vector<RobotTouch> robot_contacts;
  const RobotSnapshot* Find(const std::string& robot) const;
};

struct RobotMove {
  std::string robot;
  Eigen::Vector3d position;  // torso centre
  Eigen::Quaterniond orientation;
  bool reset_joints = false;
};

struct BallMove {
  Eigen::Vector3d position;
  Eigen::Vector3d velocity;
};

struct JointVelocity {
  std::string joint;      // the model's name (hj1)
  double velocity = 0.0;  // rad/s, within the robot type's limit
};

struct WorldRequests {
  std::vector<RobotMove> moves;
  std::optional<BallMove> ball;
  std::map<std::string, std::vector<JointVelocity>> joints;  // by robot
};

struct SessionOptions {
  uint64_t seed = 1;
  bool sync_mode = false;
  int sync_grace_cycles = 5;  // cycles after `scene` before an agent's (syn) is awaited
  VisionParams vision;
  GameRules rules;
};

// Who sends trainer commands. Only an operator may end, restart or rewrite
// the match (IsMatchControl, trainer.h); such a command from anyone else is
// refused ("trainer.not_operator") and changes nothing. Which connection is an
// operator's is the participant's business (its address allowlist).
enum class TrainerRole { kTrainer, kOperator };

// Why an agent's input was refused (counted per kind, logged by the participant).
struct SessionIssue {
  int agent = -1;  // -1: the trainer
  std::string kind;
  std::string detail;
};

class Session {
 public:
  // robots: the world's robots the agents may take, in order (names); park:
  // where each waits when no agent uses it (its torso pose at the start).
  Session(SessionOptions options, std::vector<std::string> robots, std::vector<RobotMove> park);

  // The robot type each of `robots` was built as (0..4, -1 not known; the scene's nao_type), in the same order.
  // An agent's `scene` then takes a free robot of the type it asks for; when none is free, another free robot
  // serves (the last free one), as all robots did before types were built, and a note says so (TakeNotes).
  void SetRobotTypes(std::vector<int> types);
  // What the participant should log that is not a refusal (a robot of another type serving an agent).
  std::vector<std::string> TakeNotes() { return std::exchange(notes_, {}); }

  int Connect();  // a new agent's id
  void Disconnect(int agent);
  void Receive(int agent, const std::string& payload);
  void Trainer(const std::string& payload, TrainerRole role);

  bool ReadyToStep() const;
  WorldRequests TakeRequests();
  void Advance(WorldSnapshot world);
  std::vector<std::pair<int, std::string>> TakeOutputs();
  std::vector<SessionIssue> TakeIssues();
  std::vector<int> TakeKicked();        // agents to disconnect (trainer kill, turfResetTeam)
  std::string TakeMonitorOutput();      // game predicates for monitors, every 2nd cycle (0.04 s)
  std::string MonitorGreeting() const;  // a new monitor's first frame: environment and game
  bool quit_requested() const { return quit_; }

  int agents() const { return static_cast<int>(agents_.size()); }
  int agents_with_robot() const;
  uint64_t cycle() const { return cycle_; }
  const Game& game() const { return game_; }
  // Agents not synced (sync mode), for diagnostics.
  std::vector<int> Waiting() const;

  // The league's state, for a snapshot next to the world's (the kernel's):
  // the cycle, the game (referee), the radio's messages in flight and
  // capacities, the beam noise, the world requests not yet taken (beams,
  // ball placements, the joint velocities held for the next step), the last
  // world seen (say positions, trainer moves), and per player, keyed by
  // (side, unum): team, robot type, robot, vision noise generator and
  // calibration offset, perception count (when it sees), pending GS
  // announcement. Not in it: connection-level things (agent ids, sync flags,
  // outputs and issues not yet taken, monitor frames) and agents without a
  // team (no init), whose own state a restore leaves as it is (the world
  // requests not yet taken are all the snapshot's, for every robot).
  std::string SaveLeague() const;
  // Restores what SaveLeague saved; "" on success, else why, and then
  // nothing changed. The players connected now must be exactly the
  // snapshot's: each (side, unum) of the snapshot connected and in a team, in
  // the same robot, and no other player in a team; otherwise the snapshot is
  // refused (say, before the agents have reconnected). A player's id stays
  // the connection's; its league state becomes the snapshot's. A restored run
  // sends the same bytes as the saved one when the players are the same
  // connections; after a player reconnected, vision lists the other players
  // in the new connection order (and draws their noise in that order).
  std::string RestoreLeague(std::string_view snapshot);

 private:
  struct Agent {
    int id = 0;
    int robot = -1;  // index into robots_, -1 before `scene`
    int type = 0;
    bool inited = false;
    bool announce = false;  // the next GS carries unum and team
    Side side = Side::kLeft;
    int unum = 0;
    std::string team;
    uint64_t scene_cycle = 0;
    uint64_t perceptions = 0;
    bool synced = false;
    bool kicked = false;  // waiting for the participant to disconnect it: its input is ignored
    Eigen::Vector3d calibration = Eigen::Vector3d::Zero();
    Rng rng;
    std::optional<std::string> say;
  };

  Agent* FindAgent(int id);
  Agent* FindPlayer(Side side, int unum);
  void Issue(int agent, const std::string& kind, const std::string& detail);
  std::optional<size_t> FreeRobot(int type, bool* other_type) const;
  void TakeRobot(Agent* agent, int type);
  void ReleaseRobot(Agent* agent);
  void LeaveTeam(Agent* agent);
  void Kick(Agent* agent);
  void PlaceAgent(Agent* agent, const Pose2& pose);
  std::string Perceive(Agent* agent, const WorldSnapshot& world);
  SeeItems See(const Agent& agent, const RobotSnapshot& robot, const WorldSnapshot& world);
  const std::vector<int>& HingeIndex(int type, const RobotSnapshot& robot);
  void CheckSelfCollisions(const WorldSnapshot& world);
  void DropBall();
  struct RefereeView;
  RefereeView ViewOf(const WorldSnapshot& world, const std::vector<Toucher>& touchers) const;
  void ClearPlayers(const std::vector<Clearing>& clearings, RefereeView* view);
  void CheckFouls(const RefereeView& view, const WorldSnapshot& world, const Eigen::Vector3d& ball);
  void ApplyFreezes(std::map<std::string, std::vector<JointVelocity>>* joints) const;

  SessionOptions options_;
  std::vector<std::string> robots_;
  std::vector<RobotMove> park_;
  std::vector<int> robot_types_;  // per robot, -1 not known
  std::vector<std::string> notes_;
  std::vector<int> robot_owner_;  // agent id per robot, -1 free
  std::map<int, Agent> agents_;
  int next_agent_ = 1;
  uint64_t cycle_ = 0;
  Game game_;
  Radio radio_;
  SelfCollisionRule self_collision_;
  FoulReferee fouls_;
  Field3dGeometry field_;
  Rng beam_rng_;
  WorldRequests requests_;
  std::map<std::string, std::vector<JointVelocity>> held_joints_;  // asked last cycle, for this step
  std::vector<std::pair<int, std::string>> outputs_;
  std::vector<SessionIssue> issues_;
  std::vector<int> kicked_;
  std::string monitor_;
  bool quit_ = false;
  std::optional<WorldSnapshot> last_;
  // rcssserver3d's accelerometer (ACC): the torso's velocity change over the cycle before the last, from its poses
  // of the last four cycles (newest last; a move shifts them to end where it put the torso), in the torso's frame
  // of the cycle before, gravity added. Fewer poses: the world's own accelerometer.
  struct TorsoPose {
    Eigen::Vector3d position = Eigen::Vector3d::Zero();
    Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
    template <class Io>
    friend void Fields(Io& io, IoRef<Io, TorsoPose> t) {
      io(t.position, t.orientation);
    }
  };
  std::map<std::string, std::vector<TorsoPose>> torso_poses_;
  void RecordTorsoPoses(const WorldSnapshot& world);
  void StartTorsoPosesAt(const std::string& robot, const Eigen::Vector3d& position);
  std::optional<Eigen::Vector3d> ReferenceAcc(const std::string& robot) const;
  std::vector<VisionPlayer> players_;            // this cycle's, for every agent's vision
  std::map<int, std::vector<int>> hinge_index_;  // robot type -> HingeIndex
  size_t hinge_joint_count_ = 0;

  friend struct TrainerCommandVisitor;
};

}  // namespace turf::simspark
