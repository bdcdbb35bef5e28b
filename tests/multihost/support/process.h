// A real child process for the multi-host, fault and launch tests: argv (and
// extra environment), output to a log file, its pid for signals, and SIGTERM
// then SIGKILL on scope exit.
#pragma once

#include <sys/types.h>

#include <chrono>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace turf::test {

class Process {
 public:
  using Env = std::vector<std::pair<std::string, std::string>>;
  // `name` names the log file (tests/multihost_logs/<name>_<pid>.log).
  Process(std::string name, std::vector<std::string> argv, Env env = {});
  ~Process();
  Process(const Process&) = delete;
  Process& operator=(const Process&) = delete;

  pid_t pid() const { return pid_; }
  bool Running();
  void Signal(int sig);
  // Waits for the exit; the status as waitpid reports it, nullopt on timeout.
  std::optional<int> Wait(std::chrono::milliseconds timeout);
  // SIGTERM, up to `grace`, then SIGKILL; the exit status (-1 if never started).
  int Stop(std::chrono::milliseconds grace = std::chrono::milliseconds(3000));
  void Kill();  // SIGKILL at once: a crash, as far as peers can tell
  const std::string& log_path() const { return log_path_; }
  std::string Log() const;

 private:
  std::string name_;
  std::string log_path_;
  pid_t pid_ = -1;
  int status_ = -1;
};

// tests/multihost_logs/ of this build (made if missing): logs and the
// profiles tests write.
std::string LogDir();

// An executable of this build, e.g. Built("participants/sim/turf-sim").
std::string Built(const std::string& relative);

// A UDP port that was free a moment ago on 127.0.0.1.
int FreePort();

}  // namespace turf::test
