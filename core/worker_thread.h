// One long-lived thread that runs its owner's jobs one at a time: what std::async(std::launch::async, job) and
// future.get() do, without starting a thread per job. The RCSSServerMJ front-end steps the world this way while it
// formats perceptions, once per 20 ms cycle; at 5x real time that is every 4 ms, and a new thread each time costs
// its start, its stack's page faults and a cold cache.
//
// With a spin budget, the worker (for its next job) and Wait() (for the job's end) first poll for up to that long,
// yielding the core between polls, before they sleep. The constraint islands' groups (core/legged/legged_islands.h)
// meet at every 5 ms physics step, a few hundred microseconds apart, and waking a sleeping thread on a virtual
// machine takes 50 us and more (idle virtual CPUs halt): polling made the 22-agent RCSSServerMJ bench 6 % faster
// (docs/performance.md). Without a budget both sleep at once.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <utility>

#include "core/pinned.h"

namespace turf {

class WorkerThread : Pinned {
 public:
  explicit WorkerThread(std::chrono::microseconds spin = {}) : spin_(spin), thread_([this] { Loop(); }) {}
  // Waits for a job that is running, then stops the thread.
  ~WorkerThread() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      quit_ = true;
      posted_.store(true, std::memory_order_release);
    }
    changed_.notify_all();
    thread_.join();
  }

  // Starts `job` on the worker. One job at a time: call Wait() before the next Start().
  void Start(std::function<void()> job) {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      job_ = std::move(job);
      done_ = false;
      posted_.store(true, std::memory_order_release);
      finished_.store(false, std::memory_order_release);
    }
    changed_.notify_all();
  }
  // Returns when the job has finished; rethrows what it threw.
  void Wait() {
    Poll(finished_);
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait(lock, [this] { return done_; });
    if (std::exception_ptr e = std::exchange(error_, nullptr)) std::rethrow_exception(e);
  }

 private:
  void Loop() {
    std::unique_lock<std::mutex> lock(mutex_);
    while (true) {
      if (!job_ && !quit_) {
        lock.unlock();
        Poll(posted_);
        lock.lock();
      }
      changed_.wait(lock, [this] { return quit_ || job_; });
      if (!job_) return;  // quit with nothing to run
      std::function<void()> job = std::exchange(job_, nullptr);
      posted_.store(false, std::memory_order_relaxed);
      lock.unlock();
      std::exception_ptr error;
      try {
        job();
      } catch (...) {
        error = std::current_exception();
      }
      lock.lock();
      error_ = error;
      done_ = true;
      finished_.store(true, std::memory_order_release);
      changed_.notify_all();
    }
  }

  // Returns when `flag` is set or the spin budget is spent; the caller then decides under the lock.
  void Poll(const std::atomic<bool>& flag) const {
    if (spin_.count() <= 0) return;
    const auto deadline = std::chrono::steady_clock::now() + spin_;
    while (!flag.load(std::memory_order_acquire) && std::chrono::steady_clock::now() < deadline)
      std::this_thread::yield();
  }

  const std::chrono::microseconds spin_;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::function<void()> job_;         // under mutex_
  std::exception_ptr error_;          // under mutex_
  bool done_ = true;                  // under mutex_
  bool quit_ = false;                 // under mutex_
  std::atomic<bool> posted_{false};   // a job or quit_ is set: what Poll watches for the worker
  std::atomic<bool> finished_{true};  // done_: what Poll watches for Wait()
  std::thread thread_;                // last: starts after the members above exist
};

}  // namespace turf
