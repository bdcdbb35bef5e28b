// say / hear between agents (shared/protocols/simspark.md, "hear"). Pure:
// messages said during a cycle are collected, then handed to each listener.
// A speaker hears its own message back ("self") always; others hear it within
// max_distance, with the direction in the listener team's field frame. Each
// listener has a capacity of one teammate and one opponent message per two
// cycles (the reference server's token bucket: +1 per cycle up to 2, a message
// costs 2); extra messages are lost. Message syntax (1..20 printable chars, no
// parentheses) is checked by the say effector's decoder, not here.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "core/state_io.h"
#include "kernel/simspark/types.h"

namespace turf::simspark {

struct Speaker {
  std::string team;  // team name (as heard)
  Side side = Side::kLeft;
  int unum = 0;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // field frame (e.g. the torso centre)
};

struct RadioParams {
  double max_distance = 50.0;  // m, heard when distance <= this
  int capacity_max = 2;        // per listener and category (teammates, opponents)
  int capacity_gain = 1;       // per cycle
  int capacity_cost = 2;       // per message heard
};

class Radio {
 public:
  explicit Radio(RadioParams params = {}) : params_(params) {}

  // Collected until EndCycle; a speaker's later message in the same cycle replaces its earlier one.
  void Say(const Speaker& who, const std::string& message, double game_time);
  // The messages for one listener this cycle (call once per listener per cycle):
  // its own, then teammates', then opponents', each in the order said.
  std::vector<Heard> Deliver(const Speaker& listener, uint64_t cycle);
  // Forgets this cycle's messages (the listeners' capacities persist).
  void EndCycle();
  // Forgets a listener's capacity (e.g. when the agent leaves).
  void Forget(Side side, int unum);

  // The messages said this cycle and the listeners' capacities, for
  // snapshots (the parameters are configuration, not saved). A restore that
  // fails leaves the radio unchanged.
  void Save(StateWriter& out) const;
  void Restore(StateReader& in);

 private:
  struct Said {
    Speaker speaker;
    std::string message;
    double game_time = 0.0;
    template <class Io>
    friend void Fields(Io& io, IoRef<Io, Said> s) {
      io(s.speaker.team, s.speaker.side, s.speaker.unum, s.speaker.position, s.message, s.game_time);
    }
  };
  struct Capacity {
    int teammates = 0;
    int opponents = 0;
    uint64_t cycle = 0;
    template <class Io>
    friend void Fields(Io& io, IoRef<Io, Capacity> c) {
      io(c.teammates, c.opponents, c.cycle);
    }
  };

  RadioParams params_;
  std::vector<Said> said_;
  std::map<std::pair<int, int>, Capacity> capacity_;  // (side, unum)
};

}  // namespace turf::simspark
