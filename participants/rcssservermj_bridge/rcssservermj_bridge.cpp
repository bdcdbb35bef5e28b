#include "participants/rcssservermj_bridge/rcssservermj_bridge.h"

#include <spdlog/spdlog.h>

#include <chrono>
#include <cmath>
#include <vector>

#include "codecs/rcssservermj/session.h"
#include "core/worker_thread.h"
#include "participants/lockstep_front_end/front_end_handle_impl.h"
#include "participants/lockstep_front_end/league_front_end.h"
#include "participants/rcssservermj_bridge/legged_snapshot.h"

namespace turf {

namespace {

// The options as the front-end runs them: the sequential loop and as fast as possible imply sync mode. Throws
// std::invalid_argument for a bad rule book or field (before any port is bound).
RcssServerMjOptions Checked(RcssServerMjOptions o) {
  if (o.sequential || !o.realtime) o.sync_mode = true;
  rcssservermj::SessionOptions check;
  check.rules = o.rules;
  check.field = o.field;
  rcssservermj::Session probe(check, {});
  return o;
}

}  // namespace

// The RCSSServerMJ league over the shared engine (league_front_end.h): monitor clients from allowed addresses only,
// init and per-cycle sync, PD joint commands, and perceptions sent while the world steps.
class RcssServerMjBridgeImpl : public LeagueFrontEnd<RcssServerMjBridgeImpl, RcssServerMjWorld, rcssservermj::Session,
                                                     RcssServerMjOptions, RcssServerMjStats> {
 public:
  static constexpr LeagueNames kNames = {"RCSSServerMJ", "turf-rcssservermj-bridge", "monitor", "closed by the server",
                                         "sent no message within the agent timeout"};

  // The robots have no force sensors; the monitor allowlist refuses other addresses.
  RcssServerMjBridgeImpl(RcssServerMjOptions options, dds::Bus* bus)
      : LeagueFrontEnd(Checked(std::move(options)), bus, false, &RcssServerMjOptions::monitor_allow) {}

  void LogStart() {
    spdlog::info("RCSSServerMJ agents: TCP {}:{}; monitor commands: TCP {}:{}; {}{}{}", options_.listen, agent_port(),
                 options_.listen, monitor_port(), options_.realtime ? "real time" : "as fast as possible",
                 options_.sync_mode ? ", sync mode" : "", options_.sequential ? ", sequential loop" : "");
    spdlog::info("monitor-port clients allowed from: {}", monitor_allow_.Describe());
  }
  bool Paced() const { return options_.realtime; }
  std::chrono::milliseconds AgentTimeout() const { return options_.agent_timeout; }
  bool Idle() const { return session_->active_agents() == 0 && !session_->HasPendingInit(); }

  std::unique_ptr<rcssservermj::Session> Start() {
    const std::vector<rcssservermj::SceneRobot> robots = RcssServerMjWorld::SceneRobots(*link_);
    int t1 = 0, k1 = 0;
    for (const rcssservermj::SceneRobot& r : robots) {
      t1 += r.model == "T1";
      k1 += r.model == "K1";
    }
    spdlog::info("scene '{}': {} T1 and {} K1 robots for agents, {} physics steps of {} ms per 20 ms cycle; rules {}",
                 link_->scene_info().name(), t1, k1, steps_, link_->step_s() * 1e3, options_.rules);
    if (std::abs(steps_ * link_->step_s() - kCycleSeconds) > 1e-9)
      spdlog::warn("the scene's physics step does not divide 20 ms: a cycle is {} ms", steps_ * link_->step_s() * 1e3);
    spdlog::info("publishing {} (steps, moves, PD joint commands); subscribing {}, {}",
                 link_->TopicName(dds::Topic::kControl), link_->TopicName(dds::Topic::kRobotsState),
                 link_->TopicName(dds::Topic::kControlReply));
    rcssservermj::SessionOptions o;
    o.sync_mode = options_.sync_mode;
    o.sequential = options_.sequential;
    o.rules = options_.rules;
    o.field = options_.field;
    o.seed = options_.seed;
    return std::make_unique<rcssservermj::Session>(o, robots);
  }

  // The reference's order: the actions, then the perceptions of the state before this step go out while the world
  // steps (the world on the stepper thread, so the agents think meanwhile), then the referee; the sequential loop's
  // perceptions of the state after it (SendOutputs).
  template <class Step>
  bool WhileStepping(Step&& step) {
    for (int agent : session_->TakeKicked()) DropAgent(agent, kNames.kicked);
    bool stepped = false;
    stepper_.Start([&] { stepped = step(); });
    try {
      SendOutputs();
    } catch (...) {
      stepper_.Wait();  // the job uses this frame's locals
      throw;
    }
    stepper_.Wait();
    return stepped;
  }

  void SendOutputs() {
    for (const auto& [agent, perception] : session_->TakePerceptions())
      SendToAgent(agent, rcssservermj::FormatPerception(perception));
    server_->FlushDrops();
  }

  void CountAgents(RcssServerMjStats& s) const {
    s.agents = session_->agents();
    s.active_agents = session_->active_agents();
  }

  bool AdmitMonitor(FrontEndClient&, const std::string& address, std::string*) {
    if (!monitor_allow_.Allows(address)) {
      rejects_.Reject("monitor_not_allowed",
                      fmt::format("{} refused: not in the monitor allowlist ({})", address, monitor_allow_.Describe()));
      return false;  // the peer's destructor closes it
    }
    server_->connections().Reject("monitor_connected", address);
    return true;
  }

  void FromMonitor(FrontEndClient&, const std::string& payload) { session_->Monitor(payload); }

  std::string MatchStatus() const {
    const rcssservermj::Referee& r = session_->referee();
    return fmt::format("({} active) play mode {} play time {:.2f} score {}:{}", session_->active_agents(),
                       rcssservermj::PlayModeName(r.play_mode()), r.play_time(), r.score(rcssservermj::Side::kLeft),
                       r.score(rcssservermj::Side::kRight));
  }

 private:
  WorkerThread stepper_;  // steps the world while the perceptions go out; last: stopped before the rest goes
};

template class FrontEndHandle<RcssServerMjBridgeImpl, RcssServerMjOptions, RcssServerMjStats>;
template class LeagueHandle<RcssServerMjBridgeImpl, RcssServerMjOptions, RcssServerMjStats>;

}  // namespace turf
