// What a test's reader helpers share: readers' on_data wake a waiting test thread (participants/common/wakeup.h),
// which re-checks its condition until it holds or a deadline passes. No polling, no sleeps.
#pragma once

#include <chrono>
#include <functional>

#include "participants/common/wakeup.h"

namespace turf::test {

class WakeWait {
 public:
  // For a reader's on_data (any thread).
  void Wake() { wakeup_.Notify(); }
  // Calls `check()` at once and after every wake until it answers true; false at `deadline`. A wake that comes
  // while `check()` runs is kept, so none is lost.
  bool Until(std::chrono::steady_clock::time_point deadline, const std::function<bool()>& check) {
    while (!check()) {
      if (std::chrono::steady_clock::now() >= deadline) return false;
      wakeup_.WaitUntil(deadline);
    }
    return true;
  }

 private:
  Wakeup wakeup_;
};

}  // namespace turf::test
