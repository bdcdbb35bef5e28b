// Linked into every test executable (turf_test): a test process that is still running at its deadline prints the
// stack of every thread (through gdb, when installed) and aborts, so that a hang in CI leaves evidence rather than
// ctest's bare "Timeout". The deadline is TURF_TEST_WATCHDOG_S seconds (default 270, under the suite's 300 s
// ctest timeout; 0 switches the watchdog off). Stdout is line-buffered so that what gtest printed before a hang
// (its failure messages) is not lost with the process.
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <string>
#include <thread>

namespace {

double DeadlineSeconds() {
  const char* text = std::getenv("TURF_TEST_WATCHDOG_S");
  if (text == nullptr || *text == '\0') return 270.0;
  char* end = nullptr;
  const double seconds = std::strtod(text, &end);
  if (end == text || *end != '\0' || !(seconds >= 0.0)) {
    std::fprintf(stderr, "watchdog: TURF_TEST_WATCHDOG_S='%s' is not a number of seconds; using 270\n", text);
    return 270.0;
  }
  return seconds;
}

// Every thread's stack, from gdb attached to this process, on stderr.
void PrintStacks() {
  prctl(PR_SET_PTRACER, PR_SET_PTRACER_ANY, 0, 0, 0);  // let the child attach under Yama's ptrace scope 1
  const std::string pid = std::to_string(getpid());
  std::fflush(stdout);
  std::fflush(stderr);
  const pid_t child = fork();
  if (child == 0) {
    dup2(STDERR_FILENO, STDOUT_FILENO);
    execlp("gdb", "gdb", "-nx", "-batch", "-p", pid.c_str(), "-ex", "thread apply all bt", static_cast<char*>(nullptr));
    static const char kNoGdb[] = "watchdog: gdb is not installed (scripts/setup.sh installs it): no stacks\n";
    [[maybe_unused]] const ssize_t n = write(STDERR_FILENO, kNoGdb, sizeof(kNoGdb) - 1);
    _exit(127);
  }
  if (child > 0) waitpid(child, nullptr, 0);
}

class Watchdog {
 public:
  Watchdog() {
    setvbuf(stdout, nullptr, _IOLBF, 0);
    const double seconds = DeadlineSeconds();
    if (seconds > 0.0) thread_ = std::thread([this, seconds] { Watch(seconds); });
  }
  ~Watchdog() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      done_ = true;
    }
    wake_.notify_all();
    if (thread_.joinable()) thread_.join();
  }
  Watchdog(const Watchdog&) = delete;
  Watchdog& operator=(const Watchdog&) = delete;

 private:
  void Watch(double seconds) {
    std::unique_lock<std::mutex> lock(mutex_);
    if (wake_.wait_for(lock, std::chrono::duration<double>(seconds), [this] { return done_; })) return;
    lock.unlock();
    std::fprintf(stderr,
                 "watchdog: this test process has run for %.0f s (TURF_TEST_WATCHDOG_S): the stacks of its threads "
                 "follow, then it aborts\n",
                 seconds);
    PrintStacks();
    std::abort();
  }

  std::mutex mutex_;
  std::condition_variable wake_;
  bool done_ = false;
  std::thread thread_;
};

const Watchdog g_watchdog;

}  // namespace
