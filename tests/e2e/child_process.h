// Runs a turf executable as a real child process for end-to-end tests, with
// its output in a log file; stopped with SIGTERM (then SIGKILL) on scope exit.
#pragma once

#include <sys/types.h>

#include <chrono>
#include <string>
#include <vector>

namespace turf::test {

class ChildProcess {
 public:
  ChildProcess(std::string name, std::vector<std::string> argv);
  ~ChildProcess();
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  bool Running();
  // SIGTERM, wait up to `grace`, then SIGKILL. Returns the exit status as
  // `waitpid` reports it (decode with WIFEXITED etc.), or -1 if not started.
  int Stop(std::chrono::milliseconds grace = std::chrono::milliseconds(3000));
  void Kill();  // SIGKILL at once (a crash, as far as peers can tell)
  const std::string& log_path() const { return log_path_; }
  std::string Log() const;  // the output so far

 private:
  std::string name_;
  std::string log_path_;
  pid_t pid_ = -1;
  int status_ = -1;
};

// An executable built by this project, e.g. BuiltBinary("participants/sim/turf-sim").
std::string BuiltBinary(const std::string& relative);

// A UDP port that was free a moment ago on 127.0.0.1.
int FreeUdpPort();

}  // namespace turf::test
