#include "participants/common/cycle_loop.h"

#include <algorithm>

namespace turf {

namespace {

using Clock = std::chrono::steady_clock;

struct Due {
  bool time_ok;
  bool agents_ok;
};

}  // namespace

bool RunCycleLoop(const CycleLoopOptions& o, const CycleLoopHooks& h, const std::function<bool()>& stop) {
  auto next_cycle = Clock::now();
  auto waiting_since = Clock::now();
  auto next_status = Clock::now() + std::chrono::seconds(10);
  while (!stop() && !h.quit()) {
    const bool idle = o.sync && h.idle();
    const bool answered = o.sync && !idle && h.ready();
    Clock::duration wait = o.cycle;
    if (o.paced) {
      wait = std::max(next_cycle - Clock::now(), Clock::duration::zero());
    } else if (answered) {
      wait = Clock::duration::zero();
    }
    h.poll(std::chrono::duration_cast<std::chrono::milliseconds>(wait));
    const auto after = Clock::now();
    if (after >= next_status) {
      h.status();
      next_status = after + std::chrono::seconds(10);
    }
    const Due due{!o.paced || after >= next_cycle, !o.sync || (!idle && h.ready())};
    if (!due.time_ok || !due.agents_ok) {
      const bool late = o.agent_timeout.count() > 0 && after - waiting_since > o.agent_timeout;
      if (o.sync && !idle && !due.agents_ok && late) {
        h.drop_waiting();
        waiting_since = after;
      }
      continue;
    }
    if (h.waited) h.waited(Clock::now() - waiting_since);
    if (!h.cycle()) return false;
    next_cycle = std::max(next_cycle + o.cycle, Clock::now());  // late: no catching up
    waiting_since = Clock::now();
    if (o.end_cycles >= 0 && static_cast<int64_t>(h.cycles()) >= o.end_cycles) break;
  }
  return true;
}

}  // namespace turf
