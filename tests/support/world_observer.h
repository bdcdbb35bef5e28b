// Any other participant on a test's domain: turf-sim's newest world state and clock over DDS, and a wait for a
// condition on them with a deadline (woken by the readers, not by polling).
#pragma once

#include <turf/idl/ClockPubSubTypes.h>
#include <turf/idl/WorldStatePubSubTypes.h>

#include <chrono>
#include <functional>
#include <memory>
#include <vector>

#include "dds/participant.h"
#include "tests/support/wake_wait.h"

namespace turf::test {

class WorldObserver {
 public:
  explicit WorldObserver(const dds::ParticipantOptions& o)
      : participant_(o),
        state_(participant_.MakeReader(dds::Topic::kWorldState, [this] { wake_.Wake(); })),
        clock_(participant_.MakeReader(dds::Topic::kClock, [this] { wake_.Wake(); })) {}

  // Until `done(newest state, newest clock)` holds (once a state has arrived); false after `timeout`.
  bool Wait(const std::function<bool(const idl::WorldState&, const idl::Clock&)>& done,
            std::chrono::milliseconds timeout = std::chrono::seconds(15)) {
    return wake_.Until(std::chrono::steady_clock::now() + timeout, [&] {
      std::vector<idl::WorldState> states;
      if (state_->Take(&states)) state_now_ = states.back(), has_state_ = true;
      std::vector<idl::Clock> clocks;
      if (clock_->Take(&clocks)) clock_now_ = clocks.back();
      return has_state_ && done(state_now_, clock_now_);
    });
  }
  const idl::WorldState& state() const { return state_now_; }
  const idl::Clock& clock() const { return clock_now_; }
  const dds::Participant& participant() const { return participant_; }

 private:
  WakeWait wake_;
  dds::Participant participant_;
  std::unique_ptr<dds::Reader<idl::WorldStatePubSubType>> state_;
  std::unique_ptr<dds::Reader<idl::ClockPubSubType>> clock_;
  idl::WorldState state_now_;
  bool has_state_ = false;
  idl::Clock clock_now_;
};

}  // namespace turf::test
