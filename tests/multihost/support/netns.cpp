#include "tests/multihost/support/netns.h"

#include <signal.h>
#include <sys/wait.h>

#include <array>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <regex>
#include <sstream>
#include <thread>

namespace turf::test {

namespace {

constexpr const char* kNsPrefix = "turfmh";  // turfmh<s|b><pid>x<n>
int g_instances = 0;

// Removes namespaces a crashed or killed test left behind (their pid is gone).
void RemoveStale() {
  std::string list;
  RunCommand({"ip", "netns", "list"}, &list);
  const std::regex name(std::string(kNsPrefix) + "[sb]([0-9]+)x[0-9]+");
  std::istringstream lines(list);
  for (std::string line; std::getline(lines, line);) {
    std::smatch m;
    const std::string first = line.substr(0, line.find(' '));
    if (!std::regex_match(first, m, name)) continue;
    const int pid = std::stoi(m[1]);
    if (pid != getpid() && kill(pid, 0) != 0 && errno == ESRCH) RunCommand({"ip", "netns", "del", first});
  }
}

}  // namespace

int RunCommand(const std::vector<std::string>& argv, std::string* output) {
  int fds[2];
  if (pipe(fds) != 0) return -1;
  const pid_t pid = fork();
  if (pid == 0) {
    dup2(fds[1], STDOUT_FILENO);
    dup2(fds[1], STDERR_FILENO);
    close(fds[0]);
    close(fds[1]);
    std::vector<char*> args;
    for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    execvp(args[0], args.data());
    _exit(127);
  }
  close(fds[1]);
  std::string text;
  std::array<char, 4096> buf;
  for (ssize_t n; (n = read(fds[0], buf.data(), buf.size())) > 0;) text.append(buf.data(), static_cast<size_t>(n));
  close(fds[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  if (output != nullptr) *output = text;
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

std::string TwoHosts::Unavailable() {
  if (geteuid() != 0) return "needs root (network namespaces and veth pairs); run as root to include this test";
  const std::string probe = std::string(kNsPrefix) + "s" + std::to_string(getpid()) + "x99";
  std::string out;
  if (RunCommand({"ip", "netns", "add", probe}, &out) != 0) return "`ip netns add` failed: " + out;
  RunCommand({"ip", "netns", "del", probe});
  return "";
}

TwoHosts::TwoHosts() {
  RemoveStale();
  const int n = g_instances++;
  const std::string id = std::to_string(getpid()) + "x" + std::to_string(n);
  // A /30 of 10.231.0.0/16 per test: only these namespaces ever see it.
  const int third = getpid() % 256;
  const int fourth = 4 * (n % 64);
  for (int i = 0; i < 2; ++i) {
    ns_[i] = std::string(kNsPrefix) + (i == 0 ? "s" : "b") + id;
    if_[i] = std::string(i == 0 ? "tfs" : "tfb") + id;
    ip_[i] = "10.231." + std::to_string(third) + "." + std::to_string(fourth + 1 + i);
  }
  for (int i = 0; i < 2; ++i) {
    if (!Ip({"netns", "add", ns_[i]})) return;
    created_[i] = true;
  }
  if (!Ip({"link", "add", if_[0], "netns", ns_[0], "type", "veth", "peer", "name", if_[1], "netns", ns_[1]})) return;
  for (int i = 0; i < 2; ++i) {
    if (!Ip({"-n", ns_[i], "link", "set", "lo", "up"}) ||
        !Ip({"-n", ns_[i], "addr", "add", ip_[i] + "/30", "dev", if_[i]}) ||
        !Ip({"-n", ns_[i], "link", "set", if_[i], "up"}))
      return;
  }
  // Fast DDS picks its interfaces when a participant starts: the link must be
  // up (carrier on both ends) before any process runs.
  if (!WaitForCarrier()) error_ = "the veth pair " + if_[0] + "/" + if_[1] + " did not come up within 5 s";
}

bool TwoHosts::WaitForCarrier() const {
  const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(5);
  while (std::chrono::steady_clock::now() < end) {
    bool up = true;
    for (int i = 0; i < 2; ++i) {
      std::string out;
      RunCommand({"ip", "-n", ns_[i], "link", "show", "dev", if_[i]}, &out);
      up = up && out.find("LOWER_UP") != std::string::npos && out.find("state UP") != std::string::npos;
    }
    if (up) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return false;
}

TwoHosts::~TwoHosts() {
  for (int i = 0; i < 2; ++i) {
    if (created_[i]) RunCommand({"ip", "netns", "del", ns_[i]});
  }
}

bool TwoHosts::Ip(const std::vector<std::string>& args) {
  std::vector<std::string> argv = {"ip"};
  argv.insert(argv.end(), args.begin(), args.end());
  std::string out;
  if (RunCommand(argv, &out) == 0) return true;
  std::string cmd;
  for (const std::string& a : argv) cmd += a + " ";
  if (error_.empty()) error_ = cmd + "failed: " + out;
  return false;
}

std::vector<std::string> TwoHosts::In(const std::string& ns, std::vector<std::string> argv,
                                      const std::vector<std::pair<std::string, std::string>>& env) const {
  std::vector<std::string> full = {"ip", "netns", "exec", ns};
  if (!env.empty()) {
    full.push_back("env");
    for (const auto& [key, value] : env) full.push_back(key + "=" + value);
  }
  full.insert(full.end(), argv.begin(), argv.end());
  return full;
}

bool TwoHosts::SetLink(bool up) {
  if (!Ip({"-n", ns_[1], "link", "set", if_[1], up ? "up" : "down"})) return false;
  return !up || WaitForCarrier();
}

bool TwoHosts::BlockMulticast() {
  for (int i = 0; i < 2; ++i) {
    const std::string dev = "\"" + if_[i] + "\"";
    const std::string rules =
        "table inet turf_test {\n"
        "  chain out { type filter hook output priority 0; oifname " +
        dev +
        " ip daddr 224.0.0.0/4 counter drop; }\n"
        "  chain in { type filter hook input priority 0; iifname " +
        dev + " ip daddr 224.0.0.0/4 counter drop; }\n}\n";
    const std::string file = "/tmp/" + ns_[i] + ".nft";
    std::ofstream(file) << rules;
    std::string out;
    const int status = RunCommand({"ip", "netns", "exec", ns_[i], "nft", "-f", file}, &out);
    std::remove(file.c_str());
    if (status != 0) {
      error_ = "nft -f in " + ns_[i] + " failed: " + out;
      return false;
    }
  }
  return true;
}

long TwoHosts::DroppedMulticast() const {
  long total = 0;
  for (int i = 0; i < 2; ++i) {
    std::string out;
    RunCommand({"ip", "netns", "exec", ns_[i], "nft", "list", "table", "inet", "turf_test"}, &out);
    const std::regex packets("counter packets ([0-9]+)");
    for (std::sregex_iterator it(out.begin(), out.end(), packets), end; it != end; ++it) total += std::stol((*it)[1]);
  }
  return total;
}

bool TwoHosts::DropUdp(int percent) {
  const std::string dev = "\"" + if_[1] + "\"";
  std::string rules = "table inet turf_loss\ndelete table inet turf_loss\n";
  if (percent > 0) {
    const std::string drop =
        " meta l4proto udp numgen random mod 100 < " + std::to_string(percent) + " counter drop; }\n";
    rules += "table inet turf_loss {\n  chain out { type filter hook output priority 0; oifname " + dev + drop +
             "  chain in { type filter hook input priority 0; iifname " + dev + drop + "}\n";
  }
  const std::string file = "/tmp/" + ns_[1] + "-loss.nft";
  std::ofstream(file) << rules;
  std::string out;
  const int status = RunCommand({"ip", "netns", "exec", ns_[1], "nft", "-f", file}, &out);
  std::remove(file.c_str());
  if (status != 0) error_ = "nft -f in " + ns_[1] + " failed: " + out;
  return status == 0;
}

long TwoHosts::DroppedUdp() const {
  std::string out;
  RunCommand({"ip", "netns", "exec", ns_[1], "nft", "list", "table", "inet", "turf_loss"}, &out);
  long total = 0;
  const std::regex packets("counter packets ([0-9]+)");
  for (std::sregex_iterator it(out.begin(), out.end(), packets), end; it != end; ++it) total += std::stol((*it)[1]);
  return total;
}

}  // namespace turf::test
