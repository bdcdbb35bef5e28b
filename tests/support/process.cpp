#include "tests/support/process.h"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <random>
#include <set>
#include <sstream>
#include <stdexcept>
#include <thread>

namespace turf::test {

Process::Process(std::string name, std::vector<std::string> argv, Env env) : name_(std::move(name)) {
  log_path_ = LogDir() + "/" + name_ + "_" + std::to_string(getpid()) + ".log";
  const int fd = open(log_path_.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
  pid_ = fork();
  if (pid_ == 0) {
    if (fd >= 0) {
      dup2(fd, STDOUT_FILENO);
      dup2(fd, STDERR_FILENO);
    }
    for (const auto& [key, value] : env) setenv(key.c_str(), value.c_str(), 1);
    std::vector<char*> args;
    for (std::string& a : argv) args.push_back(a.data());
    args.push_back(nullptr);
    execvp(args[0], args.data());
    _exit(127);
  }
  if (fd >= 0) close(fd);
}

Process::~Process() { Stop(); }

bool Process::Running() {
  if (pid_ <= 0) return false;
  int status = 0;
  if (waitpid(pid_, &status, WNOHANG) == pid_) {
    status_ = status;
    pid_ = -1;
    return false;
  }
  return true;
}

void Process::Signal(int sig) {
  if (pid_ > 0) kill(pid_, sig);
}

std::optional<int> Process::Wait(std::chrono::milliseconds timeout) {
  const auto end = std::chrono::steady_clock::now() + timeout;
  while (Running()) {
    if (std::chrono::steady_clock::now() >= end) return std::nullopt;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return status_;
}

int Process::Stop(std::chrono::milliseconds grace) {
  if (!Running()) return status_;
  kill(pid_, SIGTERM);
  if (auto status = Wait(grace)) return *status;
  Kill();
  return status_;
}

void Process::Kill() {
  if (pid_ <= 0) return;
  kill(pid_, SIGKILL);
  int status = 0;
  waitpid(pid_, &status, 0);
  status_ = status;
  pid_ = -1;
}

std::string Process::Log() const {
  std::ifstream in(log_path_);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string LogDir() {
  const std::string dir = std::string(TURF_BINARY_DIR) + "/tests/process_logs";
  std::filesystem::create_directories(dir);
  return dir;
}

std::string Built(const std::string& relative) { return std::string(TURF_BINARY_DIR) + "/" + relative; }

namespace {

// True if a socket of `type` binds 127.0.0.1:`port` now (it is closed again at once).
bool Binds(int type, int port) {
  const int fd = socket(AF_INET, type, 0);
  if (fd < 0) return false;
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  addr.sin_port = htons(static_cast<uint16_t>(port));
  const bool ok = bind(fd, reinterpret_cast<sockaddr*>(&addr), sizeof(addr)) == 0;
  close(fd);
  return ok;
}

}  // namespace

// Below the kernel's ephemeral range (32768 and up, what a socket bound to port 0 gets: DDS, other tests' clients),
// so nothing else is handed the port between this pick and the test's bind; away from the ports DDS derives from
// test domains (7400 + 250 x domain + 0..63) and from turf's own defaults; never the same port twice in a process.
int FreePort(int type) {
  static std::mutex mutex;
  static std::mt19937 rng(static_cast<uint32_t>(getpid()) ^
                          static_cast<uint32_t>(std::chrono::steady_clock::now().time_since_epoch().count()));
  static std::set<int> given;
  std::lock_guard<std::mutex> lock(mutex);
  std::uniform_int_distribution<int> pick(20000, 32700);
  for (int attempt = 0; attempt < 10000; ++attempt) {
    const int port = pick(rng);
    if ((port - 7400) % 250 < 64 || port == 20011 || port == 30011 || port == 30012) continue;
    if (given.count(port) != 0 || !Binds(type, port)) continue;
    given.insert(port);
    return port;
  }
  throw std::runtime_error("FreePort: no free port left in 20000..32700");
}

}  // namespace turf::test
