#include "participants/launcher/supervisor.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spdlog/spdlog.h>
#include <sys/prctl.h>
#include <sys/signalfd.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <optional>
#include <string>
#include <string_view>

#include "participants/common/process.h"

namespace turf::launch {

namespace {

using Clock = std::chrono::steady_clock;
constexpr size_t kMaxLine = 64 * 1024;

constexpr int kConfigurationError = 2;  // every turf participant's exit status for bad flags or configuration

struct Child {
  ProcessCommand command;
  pid_t pid = -1;
  int out_fd = -1;      // read end of its stdout+stderr pipe
  std::string partial;  // output after the last newline
  Clock::time_point started;
  std::optional<Clock::time_point> restart_at;
  int quick_crashes = 0;  // in a row
  bool given_up = false;  // crashed too often: not restarted until SIGUSR1
};

// The processes a match cannot go on without: when one of them keeps crashing, the launch ends.
bool Essential(const ProcessCommand& c) { return c.name == "sim" || c.name == "discovery"; }

std::string DescribeStatus(int status) {
  if (WIFEXITED(status)) return fmt::format("exit status {}", WEXITSTATUS(status));
  if (WIFSIGNALED(status))
    return fmt::format("killed by signal {} ({})", WTERMSIG(status), strsignal(WTERMSIG(status)));
  return fmt::format("status {}", status);
}

double Seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }

// In the forked child: never returns.
[[noreturn]] void ExecChild(const ProcessCommand& command, int out_fd, pid_t parent) {
  setpgid(0, 0);
  prctl(PR_SET_PDEATHSIG, SIGTERM);
  if (getppid() != parent) _exit(1);  // the launcher died before prctl
  sigset_t none;
  sigemptyset(&none);
  sigprocmask(SIG_SETMASK, &none, nullptr);
  signal(SIGPIPE, SIG_DFL);
  const int null_fd = open("/dev/null", O_RDONLY);
  if (null_fd >= 0) dup2(null_fd, STDIN_FILENO);
  dup2(out_fd, STDOUT_FILENO);
  dup2(out_fd, STDERR_FILENO);
  for (const auto& [name, value] : command.env) setenv(name.c_str(), value.c_str(), 1);
  std::vector<char*> args;
  for (const std::string& a : command.argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  execvp(args[0], args.data());
  dprintf(STDERR_FILENO, "cannot run %s: %s\n", args[0], strerror(errno));
  _exit(127);
}

class Supervisor {
 public:
  Supervisor(const std::vector<ProcessCommand>& commands, const SupervisorOptions& options) : options_(options) {
    for (const ProcessCommand& c : commands) {
      children_.push_back(Child{c, -1, -1, "", {}, std::nullopt, 0, false});
      width_ = std::max(width_, c.name.size());
    }
    sigset_t mask;
    sigemptyset(&mask);
    sigaddset(&mask, SIGINT);
    sigaddset(&mask, SIGTERM);
    sigaddset(&mask, SIGHUP);  // the terminal or SSH session closed: stop as for SIGTERM (it died without a line)
    sigaddset(&mask, SIGCHLD);
    sigaddset(&mask, SIGUSR1);  // try the processes given up on again
    sigprocmask(SIG_BLOCK, &mask, &old_mask_);
    signal_fd_ = signalfd(-1, &mask, SFD_CLOEXEC | SFD_NONBLOCK);
    old_pipe_ = signal(SIGPIPE, SIG_IGN);  // a closed stdout must not kill the supervisor
  }

  ~Supervisor() {
    for (Child& c : children_) CloseOutput(c);
    if (signal_fd_ >= 0) close(signal_fd_);
    signal(SIGPIPE, old_pipe_);
    sigprocmask(SIG_SETMASK, &old_mask_, nullptr);
  }

  int Run() {
    if (signal_fd_ < 0) {
      spdlog::critical("signalfd: {}", strerror(errno));
      return 1;
    }
    for (Child& c : children_) Start(c);
    while (!(stopping_ && !AnyAlive())) {
      Poll();
      Reap();
      StopTheLast();
      const auto now = Clock::now();
      for (Child& c : children_) {
        if (!stopping_ && c.restart_at && now >= *c.restart_at) Start(c);
      }
      if (kill_at_ && now >= *kill_at_) {
        for (Child& c : children_) {
          if (c.pid > 0) spdlog::warn("{} did not stop within {:.1f} s: SIGKILL", c.command.name, GraceSeconds());
        }
        Signal(SIGKILL);
        exit_code_ = 1;
        kill_at_.reset();
      }
    }
    for (Child& c : children_) CloseOutput(c);
    spdlog::info("all processes stopped; exit status {}", exit_code_);
    return exit_code_;
  }

 private:
  double GraceSeconds() const { return std::chrono::duration<double>(options_.grace).count(); }

  void Start(Child& c) {
    c.restart_at.reset();
    int fds[2];
    if (pipe2(fds, O_CLOEXEC) != 0) {
      spdlog::error("{}: pipe: {}", c.command.name, strerror(errno));
      Crashed(c, "could not start");
      return;
    }
    const pid_t parent = getpid();
    const pid_t pid = fork();
    if (pid == 0) ExecChild(c.command, fds[1], parent);
    close(fds[1]);
    if (pid < 0) {
      close(fds[0]);
      spdlog::error("{}: fork: {}", c.command.name, strerror(errno));
      Crashed(c, "could not start");
      return;
    }
    setpgid(pid, pid);  // also here: no window in which a signal to the group misses it
    fcntl(fds[0], F_SETFL, O_NONBLOCK);
    c.pid = pid;
    c.out_fd = fds[0];
    c.started = Clock::now();
    spdlog::info("started {} (pid {}): {}", c.command.name, pid, ShellLine(c.command));
  }

  void Poll() {
    std::vector<pollfd> fds = {{signal_fd_, POLLIN, 0}};
    std::vector<Child*> owners = {nullptr};
    for (Child& c : children_) {
      if (c.out_fd < 0) continue;
      fds.push_back({c.out_fd, POLLIN, 0});
      owners.push_back(&c);
    }
    poll(fds.data(), fds.size(), TimeoutMs());
    if (fds[0].revents & POLLIN) HandleSignals();
    for (size_t i = 1; i < fds.size(); ++i) {
      if (fds[i].revents != 0) ReadOutput(*owners[i]);
    }
  }

  int TimeoutMs() const {
    auto next = Clock::now() + std::chrono::seconds(1);
    for (const Child& c : children_) {
      if (c.restart_at) next = std::min(next, *c.restart_at);
    }
    if (kill_at_) next = std::min(next, *kill_at_);
    const auto ms = std::chrono::duration_cast<std::chrono::milliseconds>(next - Clock::now()).count();
    return static_cast<int>(std::clamp<int64_t>(ms + 1, 0, 1000));
  }

  void HandleSignals() {
    signalfd_siginfo info{};
    while (read(signal_fd_, &info, sizeof(info)) == static_cast<ssize_t>(sizeof(info))) {
      if (info.ssi_signo == SIGCHLD) continue;  // Reap() runs after every poll
      if (info.ssi_signo == SIGUSR1) {
        RetryGivenUp();
        continue;
      }
      if (!stopping_) {
        spdlog::info("{}: stopping every process", strsignal(static_cast<int>(info.ssi_signo)));
        stop_signal_at_ = Clock::now();
        BeginStop();
      } else if (Clock::now() - stop_signal_at_ < std::chrono::nanoseconds(kSameStopNs)) {
        // As the participants count it (process.h): a service manager and a terminal both signalling is one stop.
        spdlog::info("{} again within 1 s: the same stop", strsignal(static_cast<int>(info.ssi_signo)));
      } else {
        spdlog::warn("{} again: SIGKILL to every process", strsignal(static_cast<int>(info.ssi_signo)));
        Signal(SIGKILL);
        exit_code_ = 1;
      }
    }
  }

  void ReadOutput(Child& c) {
    char buf[16384];
    while (c.out_fd >= 0) {
      const ssize_t n = read(c.out_fd, buf, sizeof(buf));
      if (n > 0) {
        c.partial.append(buf, static_cast<size_t>(n));
        size_t start = 0;
        for (size_t nl = c.partial.find('\n'); nl != std::string::npos; nl = c.partial.find('\n', start)) {
          Print(c, std::string_view(c.partial).substr(start, nl - start));
          start = nl + 1;
        }
        c.partial.erase(0, start);
        if (c.partial.size() > kMaxLine) {
          Print(c, c.partial);
          c.partial.clear();
        }
        continue;
      }
      if (n < 0 && (errno == EAGAIN || errno == EINTR)) break;
      CloseOutput(c);  // EOF or error
    }
    std::fflush(stdout);
  }

  void CloseOutput(Child& c) {
    if (c.out_fd < 0) return;
    if (!c.partial.empty()) Print(c, c.partial);
    c.partial.clear();
    close(c.out_fd);
    c.out_fd = -1;
  }

  void Print(const Child& c, std::string_view line) const {
    std::fprintf(stdout, "%-*s | %.*s\n", static_cast<int>(width_), c.command.name.c_str(),
                 static_cast<int>(line.size()), line.data());
  }

  void Reap() {
    int status = 0;
    pid_t pid;
    while ((pid = waitpid(-1, &status, WNOHANG)) > 0) {
      for (Child& c : children_) {
        if (c.pid == pid) Exited(c, status);
      }
    }
  }

  void Exited(Child& c, int status) {
    ReadOutput(c);  // whatever it printed last
    CloseOutput(c);
    c.pid = -1;
    const double ran = Seconds(Clock::now() - c.started);
    if (stopping_) {
      // SIGTERM is how we asked: dying of it (no handler) is a clean stop too.
      const bool clean =
          (WIFEXITED(status) && WEXITSTATUS(status) == 0) || (WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM);
      if (!clean && exit_code_ == 0) exit_code_ = 1;
      spdlog::log(clean ? spdlog::level::info : spdlog::level::warn, "{} stopped ({})", c.command.name,
                  DescribeStatus(status));
      return;
    }
    if (WIFEXITED(status) && WEXITSTATUS(status) == 0) {
      spdlog::info("{} exited cleanly after {:.1f} s: the launch ends", c.command.name, ran);
      BeginStop();
      return;
    }
    if (WIFEXITED(status) && WEXITSTATUS(status) == kConfigurationError) {
      // Deterministic: the same flags fail the same way, so a restart would only repeat it.
      spdlog::error(
          "{} refused its configuration (exit status 2, its message is above): not restarted; the launch "
          "ends",
          c.command.name);
      exit_code_ = kConfigurationError;
      BeginStop();
      return;
    }
    if (ran >= options_.restart.stable_after) c.quick_crashes = 0;
    Crashed(c, fmt::format("{} after {:.1f} s", DescribeStatus(status), ran));
  }

  void Crashed(Child& c, const std::string& what) {
    ++c.quick_crashes;
    const RestartPolicy& r = options_.restart;
    if (c.quick_crashes > r.max_restarts) {
      if (Essential(c.command)) {
        spdlog::error("{} crashed ({}), {} times in a row: giving up, the match cannot go on", c.command.name, what,
                      c.quick_crashes);
        exit_code_ = 1;
        BeginStop();
        return;
      }
      spdlog::error(
          "{} crashed ({}), {} times in a row: giving up on it, the match goes on without it (kill -USR1 "
          "{} tries again)",
          c.command.name, what, c.quick_crashes, getpid());
      c.given_up = true;
      return;
    }
    const double delay = std::min(r.backoff_max, r.backoff_initial * std::pow(2.0, c.quick_crashes - 1));
    spdlog::warn("{} crashed ({}): restart {} of {} in {:.2f} s", c.command.name, what, c.quick_crashes, r.max_restarts,
                 delay);
    c.restart_at = Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(delay));
  }

  void RetryGivenUp() {
    for (Child& c : children_) {
      if (!c.given_up || stopping_) continue;
      spdlog::info("SIGUSR1: trying {} again", c.command.name);
      c.given_up = false;
      c.quick_crashes = 0;
      Start(c);
    }
  }

  void BeginStop() {
    if (stopping_) return;
    stopping_ = true;
    for (Child& c : children_) c.restart_at.reset();
    if (!AnyAlive()) return;
    spdlog::info("stopping: SIGTERM, then SIGKILL after {:.1f} s", GraceSeconds());
    Signal(SIGTERM, false);
    kill_at_ = Clock::now() + options_.grace;
  }

  // Once only stop_last processes are left, they get their SIGTERM too.
  void StopTheLast() {
    if (!stopping_ || last_signalled_) return;
    const bool others = std::any_of(children_.begin(), children_.end(),
                                    [](const Child& c) { return c.pid > 0 && !c.command.stop_last; });
    if (others) return;
    last_signalled_ = true;
    for (Child& c : children_) {
      if (c.pid > 0) kill(-c.pid, SIGTERM);
    }
  }

  // To every running process (but stop_last ones, unless `all`), by process
  // group: helpers it started get it too.
  void Signal(int sig, bool all = true) {
    for (Child& c : children_) {
      if (c.pid > 0 && (all || !c.command.stop_last)) kill(-c.pid, sig);
    }
  }

  bool AnyAlive() const {
    return std::any_of(children_.begin(), children_.end(), [](const Child& c) { return c.pid > 0; });
  }

  SupervisorOptions options_;
  std::vector<Child> children_;
  size_t width_ = 0;
  sigset_t old_mask_{};
  void (*old_pipe_)(int) = SIG_DFL;
  int signal_fd_ = -1;
  bool stopping_ = false;
  Clock::time_point stop_signal_at_{};  // the first stop signal's time (a second within kSameStopNs is the same stop)
  bool last_signalled_ = false;         // stop_last processes got their SIGTERM
  std::optional<Clock::time_point> kill_at_;
  int exit_code_ = 0;
};

}  // namespace

int Supervise(const std::vector<ProcessCommand>& commands, const SupervisorOptions& options) {
  Supervisor supervisor(commands, options);
  return supervisor.Run();
}

}  // namespace turf::launch
