// A participant's statistics, written by its loop and its socket hooks and read by other threads (tests, status):
// every change under one lock, and whoever waits for a condition on them woken at each change. The front-ends'
// Stats() and WaitForStats() are this (hlvs, RCSSServerMJ and SimSpark bridges). Header-only.
#pragma once

#include <chrono>
#include <condition_variable>
#include <functional>
#include <mutex>

#include "core/pinned.h"

namespace turf {

template <class T>
class WatchedStats : Pinned {
 public:
  T Get() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return value_;
  }

  // The stats as soon as `done` holds for them, or as they are when `timeout` has passed.
  T WaitFor(const std::function<bool(const T&)>& done, std::chrono::milliseconds timeout) const {
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait_for(lock, timeout, [&] { return done(value_); });
    return value_;
  }

  // Runs `change(T&)` under the lock, then wakes the waiters.
  template <class Change>
  void Update(Change&& change) {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      change(value_);
    }
    changed_.notify_all();
  }

 private:
  mutable std::mutex mutex_;
  mutable std::condition_variable changed_;
  T value_;
};

}  // namespace turf
