// What a test's reader helpers share: readers' on_data wake a waiting test thread, which re-checks its condition
// (under one lock) until it holds or a deadline passes. No polling, no sleeps.
#pragma once

#include <chrono>
#include <condition_variable>
#include <functional>
#include <mutex>

namespace turf::test {

class WakeWait {
 public:
  // For a reader's on_data (any thread).
  void Wake() {
    std::lock_guard<std::mutex> lock(mutex_);
    pending_ = true;
    changed_.notify_all();
  }
  // Calls `check()` under the lock at once and after every wake until it answers true; false at `deadline`.
  bool Until(std::chrono::steady_clock::time_point deadline, const std::function<bool()>& check) {
    std::unique_lock<std::mutex> lock(mutex_);
    while (!check()) {
      if (!changed_.wait_until(lock, deadline, [this] { return pending_; })) return false;
      pending_ = false;
    }
    return true;
  }

 private:
  std::mutex mutex_;
  std::condition_variable changed_;
  bool pending_ = false;
};

}  // namespace turf::test
