// Samples a participant's DDS readers dropped because its loop did not take them in time (the sum of the
// readers' Overflowed()): reported as refusals of kind "queue_overflow", once per increase.
#pragma once

#include <fmt/format.h>

#include <cstdint>

namespace turf {

class OverflowWatch {
 public:
  // `reject(kind, detail)`: the participant's counted, rate-limited refusal log.
  template <class Reject>
  void Check(uint64_t dropped_total, Reject&& reject) {
    if (dropped_total <= reported_) return;
    reject("queue_overflow",
           fmt::format("{} samples arrived faster than the loop could take them", dropped_total - reported_));
    reported_ = dropped_total;
  }

 private:
  uint64_t reported_ = 0;
};

}  // namespace turf
