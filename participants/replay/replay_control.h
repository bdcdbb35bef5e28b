// turf-replay's control plane: the same request and reply topics as turf-sim's (<prefix>/control and
// <prefix>/control_reply, dds/control_client.h), so the viewer's pause button and any ControlClient drive a replay.
//
// Answered: OP_PAUSE, OP_RESUME, OP_SET_TIME_MODE (TIME_REALTIME, TIME_SCALED with `speed`, TIME_FREE_RUNNING: as
// fast as possible; TIME_LOCKSTEP is refused) and OP_SEEK (`seek_time_ns`, simulation time). Every other op is
// refused with CONTROL_NOT_ALLOWED: a replay shows the recorded match and changes nothing in it. Requests are
// outside input: a NaN or out-of-range value, or an unknown op, is refused with its named error, logged and counted.
#pragma once

#include <turf/idl/SimControlPubSubTypes.h>

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "dds/bus.h"
#include "participants/replay/replay_command.h"

namespace turf {

class ReplayControl {
 public:
  using SteadyClock = std::chrono::steady_clock;
  // Makes the control reader and the reply writer on `bus` (which must outlive this).
  explicit ReplayControl(dds::Bus& bus);
  // The valid requests that arrived since the last call, in order; refused ones are answered here.
  std::vector<ReplayCommand> Take(int64_t sim_time_ns);
  // A command of this process (a terminal line): taken with the next Take().
  void Submit(ReplayCommand command);
  // Waits until a request arrives or `until`, whichever is first.
  void WaitUntil(SteadyClock::time_point until);
  // The reply to a command, once it took effect (`refusal` empty) or when it could not; none for a local one.
  void Reply(const ReplayCommand& command, int64_t sim_time_ns, const ReplayRefusal& refusal = {});
  uint64_t refused() const { return refused_; }

 private:
  std::mutex mutex_;
  std::condition_variable arrived_;
  bool pending_ = false;
  std::vector<ReplayCommand> local_;
  uint64_t refused_ = 0;
  std::unique_ptr<dds::Writer<idl::SimControlReplyPubSubType>> reply_writer_;
  std::unique_ptr<dds::Reader<idl::SimControlPubSubType>> reader_;  // last: its callback uses the members above
};

}  // namespace turf
