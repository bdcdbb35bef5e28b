// core/worker_thread.h: jobs run on one other thread, in order, Wait() returns after the job and
// rethrows what it threw; the same with a spin budget (polling before sleeping), which changes only when the threads
// sleep.
#include "core/worker_thread.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <set>
#include <stdexcept>
#include <thread>

namespace turf {
namespace {

// No polling, a budget shorter than the gaps between the jobs below, and one of an hour: polling must end when the
// job, its end or the destructor comes, not when the budget is spent (else these tests time out).
class WorkerThreadTest : public ::testing::TestWithParam<int64_t> {
 protected:
  std::chrono::microseconds spin() const { return std::chrono::microseconds(GetParam()); }
};

INSTANTIATE_TEST_SUITE_P(Spin, WorkerThreadTest, ::testing::Values(int64_t{0}, int64_t{1}, int64_t{3600000000}));

TEST_P(WorkerThreadTest, RunsEachJobOnOneOtherThreadAndWaitSeesItsResult) {
  WorkerThread worker(spin());
  std::set<std::thread::id> threads;
  int sum = 0;
  for (int i = 1; i <= 100; ++i) {
    worker.Start([&, i] {
      threads.insert(std::this_thread::get_id());
      sum += i;
    });
    worker.Wait();
    EXPECT_EQ(sum, i * (i + 1) / 2);
  }
  ASSERT_EQ(threads.size(), 1u);
  EXPECT_NE(*threads.begin(), std::this_thread::get_id());
}

TEST_P(WorkerThreadTest, WaitRethrowsTheJobsExceptionAndTheWorkerGoesOn) {
  WorkerThread worker(spin());
  worker.Start([] { throw std::runtime_error("job failed"); });
  EXPECT_THROW(worker.Wait(), std::runtime_error);
  bool ran = false;
  worker.Start([&] { ran = true; });
  worker.Wait();
  EXPECT_TRUE(ran);
  worker.Wait();  // nothing running: returns at once
}

TEST_P(WorkerThreadTest, DestroyingWaitsForARunningJob) {
  bool finished = false;
  {
    WorkerThread worker(spin());
    worker.Start([&] {
      std::this_thread::yield();
      finished = true;
    });
  }
  EXPECT_TRUE(finished);
}

}  // namespace
}  // namespace turf
