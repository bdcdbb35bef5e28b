// A real child process for the end-to-end, multi-host, fault, launch and
// browser tests: argv (and extra environment), output to a log file, its pid
// for signals, and SIGTERM then SIGKILL on scope exit.
#pragma once

#include <sys/socket.h>
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
  // `name` names the log file (LogDir()/<name>_<test pid>.log). argv[0] is a
  // path or a name looked up on PATH.
  Process(std::string name, std::vector<std::string> argv, Env env = {});
  ~Process();
  Process(const Process&) = delete;
  Process& operator=(const Process&) = delete;

  pid_t pid() const { return pid_; }
  bool Running();
  void Signal(int sig);
  // Waits for the exit; the status as waitpid reports it (decode with
  // WIFEXITED etc.), nullopt on timeout.
  std::optional<int> Wait(std::chrono::milliseconds timeout);
  // SIGTERM, up to `grace`, then SIGKILL; the exit status (-1 if never started). The default leaves room for a
  // loaded machine: a soak run saw turf-sim's Fast DDS teardown take more than 3 s after its loop had ended; a
  // process that hangs on SIGTERM still ends as killed, not exited.
  int Stop(std::chrono::milliseconds grace = std::chrono::milliseconds(10000));
  void Kill();  // SIGKILL at once: a crash, as far as peers can tell
  const std::string& log_path() const { return log_path_; }
  std::string Log() const;  // the output so far

 private:
  std::string name_;
  std::string log_path_;
  pid_t pid_ = -1;
  int status_ = -1;
};

// tests/process_logs/ of this build (made if missing): the children's logs
// and the files tests write for them (profiles).
std::string LogDir();

// An executable of this build, e.g. Built("participants/sim/turf-sim").
std::string Built(const std::string& relative);

// A port that was free a moment ago on 127.0.0.1, for a socket of `type`
// (SOCK_DGRAM: UDP, SOCK_STREAM: TCP).
int FreePort(int type = SOCK_DGRAM);

}  // namespace turf::test
