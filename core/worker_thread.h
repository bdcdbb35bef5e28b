// One long-lived thread that runs its owner's jobs one at a time: what std::async(std::launch::async, job) and
// future.get() do, without starting a thread per job. The RCSSServerMJ front-end steps the world this way while it
// formats perceptions, once per 20 ms cycle; at 5x real time that is every 4 ms, and a new thread each time costs
// its start, its stack's page faults and a cold cache.
#pragma once

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
  WorkerThread() : thread_([this] { Loop(); }) {}
  // Waits for a job that is running, then stops the thread.
  ~WorkerThread() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      quit_ = true;
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
    }
    changed_.notify_all();
  }
  // Returns when the job has finished; rethrows what it threw.
  void Wait() {
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait(lock, [this] { return done_; });
    if (std::exception_ptr e = std::exchange(error_, nullptr)) std::rethrow_exception(e);
  }

 private:
  void Loop() {
    std::unique_lock<std::mutex> lock(mutex_);
    while (true) {
      changed_.wait(lock, [this] { return quit_ || job_; });
      if (!job_) return;  // quit with nothing to run
      std::function<void()> job = std::exchange(job_, nullptr);
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
      changed_.notify_all();
    }
  }

  std::mutex mutex_;
  std::condition_variable changed_;
  std::function<void()> job_;  // under mutex_
  std::exception_ptr error_;   // under mutex_
  bool done_ = true;           // under mutex_
  bool quit_ = false;          // under mutex_
  std::thread thread_;         // last: starts after the members above exist
};

}  // namespace turf
