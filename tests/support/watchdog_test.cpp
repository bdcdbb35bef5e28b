// The test watchdog (watchdog.cpp): a test process still running at its deadline prints its threads' stacks and
// aborts. The test runs this executable again as a child whose one test hangs, with a deadline of 1 s.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <condition_variable>
#include <csignal>
#include <cstdlib>
#include <mutex>

#include "tests/support/process.h"

namespace turf::test {
namespace {

using namespace std::chrono_literals;

constexpr const char* kHangVariable = "TURF_WATCHDOG_TEST_HANG";

// Never returns: a condition nobody notifies. A named frame for the stacks to show.
[[gnu::noinline]] void HangHereForever() {
  std::mutex mutex;
  std::condition_variable never;
  std::unique_lock<std::mutex> lock(mutex);
  for (;;) never.wait(lock);
}

// Run only as the child of the test below (skipped when ctest runs it).
TEST(WatchdogChild, Hangs) {
  if (std::getenv(kHangVariable) == nullptr) GTEST_SKIP() << "the child of Watchdog.AHungTestPrintsStacksAndAborts";
  HangHereForever();
}

std::string ThisExecutable() {
  char path[4096] = {};
  const ssize_t n = readlink("/proc/self/exe", path, sizeof(path) - 1);
  return n > 0 ? std::string(path, static_cast<size_t>(n)) : std::string();
}

TEST(Watchdog, AHungTestPrintsStacksAndAborts) {
  const std::string self = ThisExecutable();
  ASSERT_FALSE(self.empty());
  Process child("watchdog_child", {self, "--gtest_filter=WatchdogChild.Hangs"},
                {{"TURF_TEST_WATCHDOG_S", "1"}, {kHangVariable, "1"}});
  const std::optional<int> status = child.Wait(120s);
  ASSERT_TRUE(status) << "the hung child was not stopped by its watchdog:\n" << child.Log();
  ASSERT_TRUE(WIFSIGNALED(*status)) << child.Log();
  EXPECT_EQ(WTERMSIG(*status), SIGABRT);
  const std::string log = child.Log();
  EXPECT_NE(log.find("[ RUN      ] WatchdogChild.Hangs"), std::string::npos) << log;  // line-buffered: not lost
  EXPECT_NE(log.find("watchdog: this test process has run for 1 s"), std::string::npos) << log;
  if (access("/usr/bin/gdb", X_OK) == 0) {
    // A container without ptrace rights (Docker's default seccomp profile) lets gdb run but not attach.
    if (log.find("ptrace: Operation not permitted") != std::string::npos) {
      RecordProperty("stacks", "gdb may not attach here (ptrace not permitted)");
    } else {
      EXPECT_NE(log.find("HangHereForever"), std::string::npos) << log;
    }
  } else {
    EXPECT_NE(log.find("gdb is not installed"), std::string::npos) << log;
  }
}

}  // namespace
}  // namespace turf::test
