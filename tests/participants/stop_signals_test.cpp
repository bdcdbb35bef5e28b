// SIGINT and SIGTERM (participants/common/process.h), in a forked child that installs them as every participant
// does: two signals at once are one stop, which ends cleanly; a second one a second or more later leaves at once.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <optional>
#include <thread>

#include "participants/common/process.h"

namespace turf {
namespace {

// A child that installs the stop signals, says so on a pipe, waits for a stop, says so again, then takes
// `teardown` to stop (a participant's teardown) and exits 0.
class Child {
 public:
  explicit Child(std::chrono::milliseconds teardown) {
    EXPECT_EQ(pipe(pipe_), 0);
    pid_ = fork();
    if (pid_ == 0) {
      InstallStopSignals();
      Say();
      while (!StopRequested()) std::this_thread::sleep_for(std::chrono::milliseconds(1));  // polling the flag
      Say();
      std::this_thread::sleep_for(teardown);
      _exit(0);
    }
  }
  ~Child() {
    if (pid_ > 0 && !status_) {
      kill(pid_, SIGKILL);
      waitpid(pid_, nullptr, 0);
    }
    close(pipe_[0]);
    close(pipe_[1]);
  }
  // Waits for the child's next word on the pipe (blocking read: the child writes it or dies).
  bool Heard() {
    char c = 0;
    return read(pipe_[0], &c, 1) == 1;
  }
  void Signal(int sig) { kill(pid_, sig); }
  int Status() {
    int status = 0;
    waitpid(pid_, &status, 0);
    status_ = status;
    return status;
  }

 private:
  void Say() { (void)!write(pipe_[1], "x", 1); }

  int pipe_[2] = {-1, -1};
  pid_t pid_ = -1;
  std::optional<int> status_;
};

TEST(StopSignals, TwoAtOnceAreOneStopThatEndsCleanly) {
  Child child(std::chrono::milliseconds(300));
  ASSERT_TRUE(child.Heard());  // the handlers are installed
  child.Signal(SIGTERM);
  child.Signal(SIGTERM);  // a launcher's and a service manager's
  const int status = child.Status();
  ASSERT_TRUE(WIFEXITED(status)) << status;
  EXPECT_EQ(WEXITSTATUS(status), 0);
}

TEST(StopSignals, ASecondOneLaterLeavesAtOnce) {
  Child child(std::chrono::seconds(60));
  ASSERT_TRUE(child.Heard());
  child.Signal(SIGINT);
  ASSERT_TRUE(child.Heard());  // it is stopping
  std::this_thread::sleep_for(std::chrono::nanoseconds(kSameStopNs) + std::chrono::milliseconds(200));
  child.Signal(SIGINT);  // an impatient Ctrl-C
  const int status = child.Status();
  ASSERT_TRUE(WIFEXITED(status)) << status;
  EXPECT_EQ(WEXITSTATUS(status), 130);
}

// Writing to a pipe whose reader is gone (a killed launcher's output pipe) fails with EPIPE; it no longer kills the
// process before it can stop cleanly (every child of a SIGKILLed `turf launch` died of SIGPIPE).
TEST(StopSignals, AGonePipesReaderKillsNothing) {
  int out[2], go[2];
  ASSERT_EQ(pipe(out), 0);
  ASSERT_EQ(pipe(go), 0);
  const pid_t pid = fork();
  if (pid == 0) {
    close(out[0]);
    close(go[1]);
    InstallStopSignals();
    char c = 0;
    if (read(go[0], &c, 1) != 1) _exit(4);  // the parent has closed the reader
    const bool failed = write(out[1], "log line\n", 9) < 0 && errno == EPIPE;
    _exit(failed ? 0 : 3);
  }
  close(go[0]);
  close(out[0]);  // the reader is gone before the child writes
  close(out[1]);
  ASSERT_EQ(write(go[1], "x", 1), 1);
  close(go[1]);
  int status = 0;
  ASSERT_EQ(waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFEXITED(status)) << "killed by signal " << (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
  EXPECT_EQ(WEXITSTATUS(status), 0);
}

// A stop asked while SIGTERM was blocked (a parent's mask, inherited across exec) is pending; installing the
// handlers unblocks it and the stop is heard, not lost and not the signal's default death.
TEST(StopSignals, OneBlockedBeforeTheHandlersIsHeardWhenTheyAreInstalled) {
  const pid_t pid = fork();
  if (pid == 0) {
    sigset_t term;
    sigemptyset(&term);
    sigaddset(&term, SIGTERM);
    if (pthread_sigmask(SIG_BLOCK, &term, nullptr) != 0) _exit(4);
    if (raise(SIGTERM) != 0) _exit(5);  // pending
    if (StopRequested()) _exit(3);
    InstallStopSignals();
    _exit(StopRequested() ? 0 : 2);
  }
  int status = 0;
  ASSERT_EQ(waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFEXITED(status)) << "killed by signal " << (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
  EXPECT_EQ(WEXITSTATUS(status), 0);
}

}  // namespace
}  // namespace turf
