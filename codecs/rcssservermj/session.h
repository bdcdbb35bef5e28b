// The RCSSServerMJ server's behaviour in front of a turf legged world, without
// sockets, DDS or clocks (shared/protocols/rcssservermj.md): agents connect,
// init, send actions and get perceptions; monitors send commands. The
// participant feeds it bytes and world snapshots and carries out the world
// requests it returns. Same shape as codecs/simspark/session.h.
//
// One cycle (0.02 s = 4 physics steps of 5 ms), in the reference's order:
//   Receive()/Monitor()   parse and queue an agent's messages / queue a
//                         monitor's; apply nothing yet
//   ReadyToStep()         sync mode: every active agent has answered every
//                         perception it was sent
//   TakeRequests()        cycle start: activate the agents that sent init,
//                         take their messages (sync: exactly one each) and
//                         apply them; then, in the parallel loop, release the
//                         perceptions of the state before this step (sent while
//                         the world steps, so the agents think meanwhile); and
//                         return the moves, ball placement and per-joint PD
//                         commands for this cycle's step
//   -- the participant steps the world one cycle --
//   Advance(snapshot)     monitor commands and the referee, then one
//                         perception per active agent (See every 2nd cycle),
//                         released at once in the sequential loop
//   TakePerceptions()     the released perceptions (FormatPerception() them)
//
// Latency: parallel loop (default), an action answering the state after step
// k acts in step k+2, as in the reference (it sends the perceptions of the
// state after step k at the start of cycle k+1, after collecting actions);
// sequential loop, in step k+1. Motor targets and gains persist
// until replaced; before the first command every joint has targets 0 and
// kp = kd = 1. Every cycle the whole set of each active robot is requested as
// sent (a target beyond the joint's range, or a tau above its effort limit,
// acts as on the reference: only the law's torque is clamped, by the world).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <cstdint>
#include <deque>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "codecs/rcssservermj/actions.h"
#include "codecs/rcssservermj/perception.h"
#include "codecs/rcssservermj/robots.h"
#include "core/rng.h"
#include "kernel/rcssservermj/referee.h"
#include "kernel/rcssservermj/vision.h"

namespace turf::rcssservermj {

inline constexpr double kCycleSeconds = 0.02;
inline constexpr double kBeamHeight = 0.6745;  // m, torso after a beam (T1; K1: its torso height + 0.001)

struct MjLink {
  std::string name;  // body name of the robot file
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();  // world <- body
};

struct MjRobotSnapshot {
  std::string name;
  std::vector<std::string> joint_names;  // MJCF names
  std::vector<double> positions;         // rad
  std::vector<double> velocities;        // rad/s
  std::array<double, 3> gyro{};          // rad/s, torso frame
  std::array<double, 3> acc{};           // m/s^2, torso frame
  std::vector<MjLink> links;
  const MjLink* FindLink(const std::string& body) const;
};

struct MjWorldSnapshot {
  double time = 0;  // s
  Eigen::Vector3d ball = Eigen::Vector3d::Zero();
  std::vector<MjRobotSnapshot> robots;
  const MjRobotSnapshot* Find(const std::string& robot) const;
};

// One joint's motor command for the world: torque = kp (q - θ) + kd (dq - θ') + tau, clamped to the joint's
// effort limit, every physics step (the legged world's PD mode).
struct PdCommand {
  std::string joint;  // MJCF joint name
  double q = 0, dq = 0, kp = 1, kd = 1, tau = 0;
};

struct RobotMove {
  std::string robot;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // torso
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
  bool reset_joints = false;  // joints to 0, every velocity 0
};

struct WorldRequests {
  std::vector<RobotMove> moves;
  std::optional<Eigen::Vector3d> ball;                   // at rest
  std::map<std::string, std::vector<PdCommand>> joints;  // by robot
};

// A robot of the scene an agent may drive: its model (T1, K1) and where it waits when nobody drives it.
struct SceneRobot {
  std::string name;
  std::string model;
  RobotMove park;
};

// Monitor messages kept for the next cycle: in sync mode no cycle runs until the agents answer, so a monitor could
// otherwise queue without bound. More are dropped, each counted as an issue (monitor_queue_full).
inline constexpr size_t kMaxQueuedMonitor = 64;

struct SessionOptions {
  bool sync_mode = false;
  bool sequential = false;  // the sequential loop (implies sync)
  std::string rules = "fifa";
  std::string field;  // empty: the rule book's
  double ball_radius = 0.11;
  uint64_t seed = 1;
  size_t max_queued = 16;  // messages an agent may have waiting; more: dropped
};

struct SessionIssue {
  int agent = -1;  // -1: a monitor
  std::string kind;
  std::string detail;
};

class Session {
 public:
  // Throws std::invalid_argument for an unknown rule book or field.
  Session(SessionOptions options, std::vector<SceneRobot> robots);

  int Connect();
  void Disconnect(int agent);
  void Receive(int agent, const std::string& payload);
  void Monitor(const std::string& payload);

  bool ReadyToStep() const;
  WorldRequests TakeRequests();
  void Advance(MjWorldSnapshot world);
  std::vector<std::pair<int, MjPerception>> TakePerceptions();
  std::vector<std::pair<int, std::string>> TakeOutputs();  // TakePerceptions(), formatted
  std::vector<SessionIssue> TakeIssues();
  std::vector<int> TakeKicked();  // agents to disconnect (refused init, flooding)
  bool quit_requested() const { return quit_; }

  int agents() const { return static_cast<int>(agents_.size()); }
  int active_agents() const;
  bool HasPendingInit() const;  // an agent waits for activation at the next cycle
  uint64_t cycle() const { return cycle_; }
  const Referee& referee() const { return referee_; }
  bool sync() const { return options_.sync_mode || options_.sequential; }
  std::vector<int> Waiting() const;  // sync mode: active agents the next step waits for

  // The league's state, for a snapshot next to the world's (the kernel's): the cycle, the referee, the kick-off
  // coin's generator, monitor messages not yet applied, the world requests not yet taken, and per player, keyed
  // by (side, number): model, robot, its persisting motor commands, perception and answer counts (sync mode),
  // its messages not yet taken; then the parallel loop's perceptions not yet released. Not in it: connection-level
  // things (agent ids, outputs and issues not yet taken, inits not yet activated).
  std::string SaveLeague() const;
  // Restores what SaveLeague saved; "" on success, else why, and then nothing changed. The active players now
  // must be exactly the snapshot's, each in the same model and robot; otherwise the snapshot is refused (say,
  // before the agents have reconnected). A player's agent id stays the connection's.
  std::string RestoreLeague(std::string_view snapshot);

 private:
  struct Agent {
    int id = 0;
    std::optional<InitAction> init;  // received, waiting for activation
    bool active = false;
    bool kicked = false;
    const MjRobotModel* model = nullptr;
    int robot = -1;
    Side side = Side::kLeft;
    int number = 0;
    std::deque<ActionMessage> queue;  // parsed on arrival
    std::vector<PdCommand> motors;    // the persisting commands, model order
    uint64_t perceptions = 0;         // released since activation
    uint64_t answers = 0;             // sync mode: messages taken
  };

  Agent* FindAgent(int id);
  bool Owes(const Agent& agent) const;  // sync mode: the next step waits for one of its messages
  void Release();                       // the pending perceptions become outputs
  Agent* FindPlayer(Side side, int number);
  void Issue(int agent, const std::string& kind, const std::string& detail);
  void Kick(Agent* agent, const std::string& why);
  void Activate(Agent* agent);
  void Apply(Agent* agent, const ActionMessage& m);
  void Beam(Agent* agent, const BeamAction& beam);
  void ApplyMonitor();
  std::optional<Side> Toucher(const MjWorldSnapshot& world) const;
  MjPerception Perceive(const Agent& agent, const MjWorldSnapshot& world, const std::vector<VisiblePlayer>* players);
  std::vector<VisiblePlayer> Players(const MjWorldSnapshot& world) const;

  SessionOptions options_;
  std::vector<SceneRobot> robots_;
  std::vector<int> owner_;  // agent per robot, -1 free
  const MjField* field_;
  std::vector<FieldMarker> markers_;
  Referee referee_;
  Rng rng_;
  std::map<int, Agent> agents_;
  int next_agent_ = 1;
  uint64_t cycle_ = 0;
  std::vector<std::string> monitor_queue_;
  WorldRequests requests_;
  std::vector<std::pair<int, MjPerception>> pending_;  // the parallel loop's perceptions, until the next cycle
  std::vector<std::pair<int, MjPerception>> outputs_;
  std::vector<SessionIssue> issues_;
  std::vector<int> kicked_;
  bool quit_ = false;

  friend struct MonitorVisitor;
};

}  // namespace turf::rcssservermj
