// The engine of a 3D-league front-end (the SimSpark and RCSSServerMJ bridges' Impl derive from it, CRTP): turf-sim's
// legged scene in lockstep (LeggedLockstep), the agent and monitor ports (FrontEndServer) with the monitor port's
// address allowlist, the league's session and the cycle loop (participants/common/cycle_loop.h). It attaches (again
// after turf-sim went away, dropping the agents: their world starts over, as with a restarted server), runs a cycle
// (the session's requests, the world's steps, the world after them into the session, its answers out), logs and
// counts the session's refusals, and connects, feeds and disconnects agents.
//
// `World` is the league's world in turf's terms (static SnapshotOf(LeggedState): the world after a step,
// Target(command): a joint command as a JointTarget, Ball(placement): a ball placement's motion). The league (`L`,
// the derived class) supplies:
//   kNames                                    its LeagueNames
//   LogStart()                                the ports and modes, once attached
//   Paced(), AgentTimeout(), Idle()           the cycle loop's pacing, sync mode's agent timeout, nobody to step for
//   Start()                                   the session for the attached scene (and its log lines)
//   WhileStepping(step) -> bool               runs step() (the world's) and what goes out meanwhile
//   SendOutputs()                             the session's answers after the cycle
//   CountAgents(Stats&)                       the agent counts into the stats
//   AdmitMonitor(client, address, greeting)   a monitor-port client (FrontEndServer::Hooks::admit)
//   FromMonitor(client, payload)              a monitor's message
//   MatchStatus()                             the match for the status line (agents with a robot, play mode,
//                                             clock, score)
// Stats has LeagueStats' fields (front_end_handle.h); Options has the fields used below. Each status line is
// preceded by where the cycles since the last one spent their wall time (CycleSplit).
#pragma once

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "codecs/simspark/framing.h"
#include "participants/common/address_allowlist.h"
#include "participants/common/cycle_loop.h"
#include "participants/common/front_end_server.h"
#include "participants/common/legged_lockstep.h"
#include "participants/common/process.h"
#include "participants/common/watched_stats.h"
#include "participants/lockstep_front_end/lockstep_world.h"

namespace turf {

// A league's names in the log and on the bus.
struct LeagueNames {
  const char* league;   // its refusal and connection logs ("SimSpark input", "SimSpark client")
  const char* client;   // the link's DDS participant and control requests
  const char* monitor;  // who sends on the monitor port ("trainer")
  const char* kicked;   // why the session closed an agent
  const char* silent;   // why sync mode dropped an agent that sent nothing
};

template <class L, class World, class Session, class Options, class Stats>
class LeagueFrontEnd {
 public:
  using StopFn = std::function<bool()>;
  static constexpr double kCycleSeconds = 0.02;

  uint16_t agent_port() const { return server_->agent_port(); }
  uint16_t monitor_port() const { return server_->monitor_port(); }
  const WatchedStats<Stats>& stats() const { return stats_; }

  bool Run(const StopFn& stop) {
    if (!Attach(stop)) return stop();
    self().LogStart();
    CycleLoopOptions loop;
    loop.paced = self().Paced();
    loop.sync = options_.sync_mode;
    loop.agent_timeout = self().AgentTimeout();
    loop.end_cycles = options_.duration > 0 ? std::llround(options_.duration / kCycleSeconds) : -1;
    CycleLoopHooks hooks;
    hooks.poll = [&](std::chrono::milliseconds timeout) {
      server_->Poll(timeout);
      for (int agent : session_->TakeKicked()) DropAgent(agent, L::kNames.kicked);
      ReportIssues();
    };
    hooks.idle = [&] { return self().Idle(); };
    hooks.ready = [&] { return session_->ReadyToStep(); };
    hooks.drop_waiting = [&] {
      for (int agent : session_->Waiting()) DropAgent(agent, L::kNames.silent);
    };
    hooks.cycle = [&] { return RunCycle(stop); };
    hooks.cycles = [&] { return session_->cycle(); };
    hooks.quit = [&] { return session_->quit_requested(); };
    hooks.status = [&] { ReportStatus(); };
    hooks.waited = [&](std::chrono::steady_clock::duration d) { split_.waiting += d; };
    if (!RunCycleLoop(loop, hooks, stop)) return false;
    if (session_->quit_requested()) spdlog::info("a {} sent (killsim): stopping", L::kNames.monitor);
    ReportStatus();
    return true;
  }

 protected:
  // `need_force`: a frame is whole only with the robots' force sensors; `monitor_allow`: the options' allowlist of
  // the monitor port.
  LeagueFrontEnd(Options options, dds::Bus* bus, bool need_force, std::vector<std::string> Options::*monitor_allow)
      : options_(std::move(options)),
        link_(MakeLockstep(options_, bus, L::kNames.client, need_force)),
        monitor_allow_(options_.*monitor_allow),
        rejects_(std::string(L::kNames.league) + " input"),
        server_(std::make_unique<FrontEndServer>(ServerOptions(options_), std::string(L::kNames.league) + " client",
                                                 &rejects_, MakeHooks())) {}
  ~LeagueFrontEnd() = default;

  void DropAgent(int agent, const std::string& why) { server_->DropAgent(agent, why); }

  // Sends a perception or message framed to an agent.
  void SendToAgent(int agent, const std::string& message) { server_->SendToAgent(agent, simspark::Frame(message)); }

  Options options_;
  std::unique_ptr<LeggedLockstep> link_;
  AddressAllowlist monitor_allow_;
  std::unique_ptr<Session> session_;
  uint32_t steps_ = 4;  // physics steps per cycle
  RejectLog rejects_;
  std::unique_ptr<FrontEndServer> server_;
  WatchedStats<Stats> stats_;

 private:
  CycleSplit split_;     // since the start
  CycleSplit reported_;  // split_ at the last status line

  L& self() { return static_cast<L&>(*this); }

  static FrontEndServer::Options ServerOptions(const Options& o) {
    return {o.listen, o.agent_port, o.monitor_port, o.max_clients, o.max_unsent, {}, true};
  }

  bool Attach(const StopFn& stop) {
    if (session_) {
      for (auto& [fd, c] : server_->clients())
        if (!c.monitor) server_->MarkDrop(fd, "turf-sim stopped answering; reconnect when it is back");
      server_->FlushDrops();
    }
    if (!link_->Attach(options_.attach_timeout, stop)) return false;
    steps_ = static_cast<uint32_t>(std::max<long>(1, std::lround(kCycleSeconds / link_->step_s())));
    session_ = self().Start();
    return true;
  }

  bool RunCycle(const StopFn& stop) {
    std::string error;
    std::vector<std::string> warnings;
    const auto requests = session_->TakeRequests();
    // The world after the step is converted in the step's job too: a league that steps on a thread of its own
    // (RCSSServerMJ's parallel loop) converts it while the last cycle's perceptions go out.
    std::optional<decltype(World::SnapshotOf(link_->state()))> world;
    const auto start = std::chrono::steady_clock::now();
    const bool stepped = self().WhileStepping([&] {
      if (!link_->Step(SendRequests(requests), steps_, options_.step_timeout, stop, &error, &warnings)) return false;
      world = World::SnapshotOf(link_->state());
      return true;
    });
    // An agent's beam or a monitor's move that turf-sim refuses (beyond its placement bounds): counted, rate-limited.
    for (const std::string& w : warnings) rejects_.Reject("refused_by_turf_sim", w);
    if (!stepped) {
      if (stop()) return true;
      spdlog::error("{}; attaching again", error);
      return Attach(stop) || stop();
    }
    const double sim_time = world->time;
    const auto stepped_at = std::chrono::steady_clock::now();
    session_->Advance(std::move(*world));
    self().SendOutputs();
    split_.world += stepped_at - start;
    split_.front_end += std::chrono::steady_clock::now() - stepped_at;
    ++split_.cycles;
    ReportIssues();
    stats_.Update([&](Stats& s) {
      s.split = split_;
      s.cycles = session_->cycle();
      s.sim_time = sim_time;
      self().CountAgents(s);
    });
    return true;
  }

  // The moves and the ball placement sent (answered before the step); the step with the joint commands.
  template <class Requests>
  idl::SimControl SendRequests(const Requests& r) {
    SendMoves(*link_, r.moves, options_.step_timeout);
    if (r.ball) {
      const BallMotion ball = World::Ball(*r.ball);
      link_->SendBall(ball.position, ball.velocity, options_.step_timeout);
    }
    return StepWith(steps_, r.joints, [](const auto& command) { return World::Target(command); });
  }

  // The session's refusals into the log, and every refusal into the stats, after each cycle and each poll: a
  // monitor's refused command counts even while no cycle runs (sync mode without agents).
  void ReportIssues() {
    for (const auto& issue : session_->TakeIssues())
      rejects_.Reject(issue.kind, issue.agent < 0 ? fmt::format("{}: {}", L::kNames.monitor, issue.detail)
                                                  : fmt::format("agent {}: {}", issue.agent, issue.detail));
    stats_.Update([&](Stats& s) {
      if (s.refused == rejects_.Total()) return;
      s.refused = rejects_.Total();
      s.refused_by_kind = rejects_.counts();
    });
  }

  void ReportStatus() {
    if (!session_) return;
    ReportSplit();
    spdlog::info("cycle {} agents {} {} refused {}", session_->cycle(), session_->agents(), self().MatchStatus(),
                 rejects_.Total());
  }

  // Where the cycles since the last status line spent their wall time.
  void ReportSplit() {
    const uint64_t cycles = split_.cycles - reported_.cycles;
    if (cycles == 0) return;
    const auto ms = [&](CycleSplit::Duration CycleSplit::*part) {
      return std::chrono::duration<double, std::milli>(split_.*part - reported_.*part).count() /
             static_cast<double>(cycles);
    };
    spdlog::info("per cycle: world {:.2f} ms, front-end {:.2f} ms, waiting {:.2f} ms ({} cycles)",
                 ms(&CycleSplit::world), ms(&CycleSplit::front_end), ms(&CycleSplit::waiting), cycles);
    reported_ = split_;
  }

  FrontEndServer::Hooks MakeHooks() {
    FrontEndServer::Hooks h;
    h.admit = [this](FrontEndClient& c, const std::string& address, std::string* greeting) {
      if (c.monitor) return self().AdmitMonitor(c, address, greeting);
      c.agent = session_->Connect();
      server_->connections().Reject("agent_connected", fmt::format("agent {} from {}", c.agent, address));
      stats_.Update([&](Stats& s) { s.agents = session_->agents(); });
      return true;
    };
    h.message = [this](FrontEndClient& c, const std::string& payload) {
      if (c.monitor) {
        self().FromMonitor(c, payload);
      } else {
        session_->Receive(c.agent, payload);
      }
    };
    h.left = [this](const FrontEndClient& c) {
      if (!c.monitor) session_->Disconnect(c.agent);
      stats_.Update([&](Stats& s) {
        ++s.dropped_clients;
        self().CountAgents(s);
      });
    };
    return h;
  }
};

}  // namespace turf
