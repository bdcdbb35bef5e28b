// core/worker_thread.h: jobs run on one other thread, in order, Wait() returns after the job and
// rethrows what it threw.
#include "core/worker_thread.h"

#include <gtest/gtest.h>

#include <set>
#include <stdexcept>
#include <thread>

namespace turf {
namespace {

TEST(WorkerThreadTest, RunsEachJobOnOneOtherThreadAndWaitSeesItsResult) {
  WorkerThread worker;
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

TEST(WorkerThreadTest, WaitRethrowsTheJobsExceptionAndTheWorkerGoesOn) {
  WorkerThread worker;
  worker.Start([] { throw std::runtime_error("job failed"); });
  EXPECT_THROW(worker.Wait(), std::runtime_error);
  bool ran = false;
  worker.Start([&] { ran = true; });
  worker.Wait();
  EXPECT_TRUE(ran);
  worker.Wait();  // nothing running: returns at once
}

TEST(WorkerThreadTest, DestroyingWaitsForARunningJob) {
  bool finished = false;
  {
    WorkerThread worker;
    worker.Start([&] {
      std::this_thread::yield();
      finished = true;
    });
  }
  EXPECT_TRUE(finished);
}

}  // namespace
}  // namespace turf
