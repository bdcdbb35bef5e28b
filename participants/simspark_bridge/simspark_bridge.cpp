#include "participants/simspark_bridge/simspark_bridge.h"

#include <spdlog/spdlog.h>

#include <chrono>
#include <vector>

#include "codecs/simspark/framing.h"
#include "codecs/simspark/session.h"
#include "participants/lockstep_front_end/front_end_handle_impl.h"
#include "participants/lockstep_front_end/league_front_end.h"
#include "participants/simspark_bridge/world_snapshot.h"

namespace turf {

namespace {

// A monitor's FrontEndClient::role: from an operator's address?
simspark::TrainerRole RoleOf(const FrontEndClient& c) { return static_cast<simspark::TrainerRole>(c.role); }

const char* RoleName(simspark::TrainerRole role) {
  return role == simspark::TrainerRole::kOperator ? "operator" : "not an operator";
}

}  // namespace

// The SimSpark league over the shared engine (league_front_end.h): trainers with operator roles, (syn) sync mode,
// joint velocities, and where a cycle's wall time goes.
class SimSparkBridgeImpl : public LeagueFrontEnd<SimSparkBridgeImpl, SimSparkWorld, simspark::Session,
                                                 SimSparkBridgeOptions, SimSparkBridgeStats> {
 public:
  static constexpr LeagueNames kNames = {"SimSpark", "turf-simspark-bridge", "trainer", "killed by the trainer",
                                         "sent no (syn) within the sync timeout"};

  // A frame is whole with the force sensors too (the feet's perceptors); operators may end the match.
  SimSparkBridgeImpl(SimSparkBridgeOptions options, dds::Bus* bus)
      : LeagueFrontEnd(std::move(options), bus, true, &SimSparkBridgeOptions::operator_allow) {}

  void LogStart() {
    spdlog::info("agents: TCP {}:{}; monitors and trainers: TCP {}:{}; {} mode", options_.listen, agent_port(),
                 options_.listen, monitor_port(), options_.sync_mode ? "sync" : "real-time");
    spdlog::info("operators (may end, restart or rewrite the match from the monitor port): {}",
                 monitor_allow_.Describe());
  }
  bool Paced() const { return !options_.sync_mode; }
  std::chrono::milliseconds AgentTimeout() const { return options_.sync_timeout; }
  // Sync mode without agents: the world waits (a run is the agents' stream alone).
  bool Idle() const { return session_->agents_with_robot() == 0; }

  std::unique_ptr<simspark::Session> Start() {
    std::vector<std::string> robots;
    std::vector<int> types;  // the Nao type each was built as (scene key nao_type), -1 not known
    for (const idl::RobotDescription& r : link_->scene_info().robots()) {
      robots.push_back(r.robot());
      types.push_back(r.robot_type());
    }
    spdlog::info("scene '{}': {} robots for agents, {} physics steps of {} ms per 20 ms cycle; turf-sim in lockstep",
                 link_->scene_info().name(), robots.size(), steps_, link_->step_s() * 1e3);
    spdlog::info("publishing {} (steps, moves, joint velocities); subscribing robots/*, {}, {}",
                 link_->TopicName(dds::Topic::kControl), link_->TopicName(dds::Topic::kWorldState),
                 link_->TopicName(dds::Topic::kControlReply));
    simspark::SessionOptions o;
    o.seed = options_.seed;
    o.sync_mode = options_.sync_mode;
    o.sync_grace_cycles = options_.sync_grace_cycles;
    auto session = std::make_unique<simspark::Session>(o, robots, SimSparkWorld::ParkPoses(*link_));
    session->SetRobotTypes(std::move(types));
    return session;
  }

  template <class Step>
  bool WhileStepping(Step&& step) {
    return step();
  }

  void SendOutputs() {
    for (const std::string& note : session_->TakeNotes()) spdlog::info("{}", note);
    for (auto& [agent, message] : session_->TakeOutputs()) SendToAgent(agent, message);
    const std::string monitor = session_->TakeMonitorOutput();
    if (!monitor.empty()) {
      const std::string framed = simspark::Frame(monitor);
      for (auto& [fd, c] : server_->clients())
        if (c.monitor) server_->Send(fd, framed);
    }
    server_->FlushDrops();
  }

  void CountAgents(SimSparkBridgeStats& s) const { s.agents = session_->agents(); }

  bool AdmitMonitor(FrontEndClient& c, const std::string& address, std::string* greeting) {
    if (monitor_allow_.Allows(address)) c.role = static_cast<int>(simspark::TrainerRole::kOperator);
    server_->connections().Reject("monitor_connected", fmt::format("{} ({})", address, RoleName(RoleOf(c))));
    *greeting = simspark::Frame(session_->MonitorGreeting());
    return true;
  }

  void FromMonitor(FrontEndClient& c, const std::string& payload) { session_->Trainer(payload, RoleOf(c)); }

  std::string MatchStatus() const {
    const simspark::Game& g = session_->game();
    return fmt::format("({} with robots) play mode {} game time {:.2f} score {}:{}", session_->agents_with_robot(),
                       simspark::PlayModeName(g.play_mode()), g.game_time(), g.score(simspark::Side::kLeft),
                       g.score(simspark::Side::kRight));
  }
};

template class FrontEndHandle<SimSparkBridgeImpl, SimSparkBridgeOptions, SimSparkBridgeStats>;
template class LeagueHandle<SimSparkBridgeImpl, SimSparkBridgeOptions, SimSparkBridgeStats>;

}  // namespace turf
