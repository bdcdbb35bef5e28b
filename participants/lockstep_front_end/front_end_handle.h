// The public face shared by the lockstep front-ends (SimSpark, RCSSServerMJ and HLVS bridges): built from the
// front-end's options, on a DDS participant of its own or on a bus it is given, Run until stopped, and its
// statistics (WatchedStats: read, or waited for). The front-end's engine `Impl` stays in its .cpp, which includes
// front_end_handle_impl.h and instantiates the template (`template class FrontEndHandle<...>;`).
//
// `Impl` has: Impl(Options, dds::Bus* bus) (null: a participant of its own), bool Run(stop) and
// const WatchedStats<StatsT>& stats() const.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>

#include "core/pinned.h"
#include "dds/bus_fwd.h"

namespace turf {

template <class Impl, class Options, class StatsT>
class FrontEndHandle : Pinned {
 public:
  // Binds the front-end's ports; throws std::runtime_error if it cannot, std::invalid_argument for bad options.
  explicit FrontEndHandle(Options options);
  // On `bus` instead of a participant of its own (the options' domain, prefix and QoS file are not used): a
  // dds::MemoryBus shared with turf-sim's node, for a front-end in turf-sim's process. The bus must outlive it.
  FrontEndHandle(Options options, dds::Bus& bus);
  ~FrontEndHandle();

  // Until stop() (polled), the match's end or a fatal error; false on an error.
  bool Run(const std::function<bool()>& stop);
  StatsT Stats() const;
  // Waits until `done` holds for the stats (they change after each cycle and when a client comes or goes) or the
  // timeout passes; the stats then.
  StatsT WaitForStats(const std::function<bool(const StatsT&)>& done, std::chrono::milliseconds timeout) const;

 protected:
  std::unique_ptr<Impl> impl_;
};

// A 3D-league front-end (SimSpark's, RCSSServerMJ's): its agent and monitor ports, as bound (0 in the options: any
// free port).
template <class Impl, class Options, class StatsT>
class LeagueHandle : public FrontEndHandle<Impl, Options, StatsT> {
 public:
  using FrontEndHandle<Impl, Options, StatsT>::FrontEndHandle;
  uint16_t agent_port() const;
  uint16_t monitor_port() const;
};

// Where a 3D-league front-end's cycles spent their wall time, summed: the world (turf-sim stepping and publishing,
// the DDS or in-memory hops, and what the league sends meanwhile), the front-end after it (the session's cycle, its
// answers out) and waiting (sync mode: for the agents' answers; real time: the 20 ms pacing).
struct CycleSplit {
  using Duration = std::chrono::steady_clock::duration;
  Duration world{}, front_end{}, waiting{};
  uint64_t cycles = 0;
};

// What a 3D-league front-end counts (league_front_end.h keeps them up to date).
struct LeagueStats {
  uint64_t cycles = 0;
  double sim_time = 0.0;  // s, after the last cycle
  int agents = 0;         // connected
  uint64_t dropped_clients = 0;
  uint64_t refused = 0;  // refused input of every kind
  std::map<std::string, uint64_t> refused_by_kind;
  CycleSplit split;  // since the start
};

}  // namespace turf
