// The 3D-league front-ends' main loop (SimSpark, RCSSServerMJ): poll the sockets, then run one 20 ms cycle when it
// is due: paced (the wall clock's next 20 ms; late cycles do not catch up) and/or synchronous (every agent the
// cycle waits for has answered). A synchronous cycle waiting longer than the agent timeout drops the agents it
// waits for. The front-end supplies what differs as hooks.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>

namespace turf {

struct CycleLoopOptions {
  bool paced = true;                           // wait for the wall clock's next cycle
  bool sync = false;                           // wait for the agents' answers
  std::chrono::milliseconds agent_timeout{0};  // sync: drop the agents a cycle waits for longer (0: never)
  std::chrono::steady_clock::duration cycle = std::chrono::milliseconds(20);
  int64_t end_cycles = -1;  // stop after this many cycles (-1: never)
};

struct CycleLoopHooks {
  std::function<void(std::chrono::milliseconds)> poll;              // sockets, at most this long; then drops and issues
  std::function<bool()> idle;                                       // sync: nobody to step for, the world waits
  std::function<bool()> ready;                                      // sync: every agent answered
  std::function<void()> drop_waiting;                               // sync: the agent timeout passed
  std::function<bool()> cycle;                                      // one cycle; false: give up
  std::function<uint64_t()> cycles;                                 // cycles run so far
  std::function<bool()> quit;                                       // a monitor ended the match
  std::function<void()> status;                                     // every 10 s
  std::function<void(std::chrono::steady_clock::duration)> waited;  // optional: the time before a cycle
};

// Until stop() or quit() or end_cycles; false when a cycle gave up.
bool RunCycleLoop(const CycleLoopOptions& options, const CycleLoopHooks& hooks, const std::function<bool()>& stop);

}  // namespace turf
