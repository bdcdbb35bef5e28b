// Wakes a participant's loop when a DDS sample arrives (readers' on_data
// callbacks run on Fast DDS's threads), so an idle loop neither spins nor
// sleeps through new input.
#pragma once

#include <chrono>
#include <condition_variable>
#include <mutex>

namespace turf {

class Wakeup {
 public:
  void Notify() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      flag_ = true;
    }
    cv_.notify_one();
  }
  // Returns at `deadline` or earlier when notified (a notification since the
  // last wait counts).
  template <class Clock, class Duration>
  void WaitUntil(std::chrono::time_point<Clock, Duration> deadline) {
    std::unique_lock<std::mutex> lock(mutex_);
    cv_.wait_until(lock, deadline, [this] { return flag_; });
    flag_ = false;
  }
  void WaitFor(std::chrono::milliseconds timeout) { WaitUntil(std::chrono::steady_clock::now() + timeout); }

 private:
  std::mutex mutex_;
  std::condition_variable cv_;
  bool flag_ = false;
};

}  // namespace turf
