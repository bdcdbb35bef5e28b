// Two hosts on one machine for the multi-host tests: network namespaces
// joined by a veth pair, each with lo up and one address of a private /30
// that only exists inside them. Names carry the test's pid; the destructor
// removes both namespaces (and with them the veth pair), and a new TwoHosts
// first removes namespaces left by test processes that no longer exist.
#pragma once

#include <fcntl.h>
#include <sched.h>
#include <unistd.h>

#include <string>
#include <utility>
#include <vector>

namespace turf::test {

// Runs argv (found on PATH) and waits; the exit status (0: success), with
// stdout and stderr in *output if given.
int RunCommand(const std::vector<std::string>& argv, std::string* output = nullptr);

class TwoHosts {
 public:
  // Why namespaces cannot be made here ("" if they can): not root, no `ip`,
  // or `ip netns add` fails.
  static std::string Unavailable();

  TwoHosts();
  ~TwoHosts();
  TwoHosts(const TwoHosts&) = delete;
  TwoHosts& operator=(const TwoHosts&) = delete;

  const std::string& error() const { return error_; }  // empty when set up
  const std::string& sim_ns() const { return ns_[0]; }
  const std::string& bridge_ns() const { return ns_[1]; }
  const std::string& sim_ip() const { return ip_[0]; }
  const std::string& bridge_ip() const { return ip_[1]; }
  const std::string& bridge_if() const { return if_[1]; }

  // argv run inside a namespace: ip netns exec <ns> [env VAR=value...] argv...
  std::vector<std::string> In(const std::string& ns, std::vector<std::string> argv,
                              const std::vector<std::pair<std::string, std::string>>& env = {}) const;
  // The bridge host's end of the link, down or up (the peer loses carrier
  // too); up returns once both ends have carrier again.
  bool SetLink(bool up);
  // nftables in both namespaces: drop multicast (224.0.0.0/4) in and out on the veth.
  bool BlockMulticast();
  // Packets the multicast rules dropped so far, both namespaces.
  long DroppedMulticast() const;
  // nftables in the bridge host: drop `percent` % of the UDP packets crossing the veth, each way, at random (0
  // removes the rule); what a lossy LAN or Wi-Fi does. `netem` would be the usual tool, but not every kernel has it.
  bool DropUdp(int percent);
  // Packets the loss rule dropped so far.
  long DroppedUdp() const;

  // Runs fn() with the calling thread inside `ns` (e.g. to open a socket
  // there: a socket stays in the namespace it was made in).
  template <class F>
  auto InNamespace(const std::string& ns, F fn) {
    const int self = open("/proc/thread-self/ns/net", O_RDONLY | O_CLOEXEC);
    const int target = open(("/run/netns/" + ns).c_str(), O_RDONLY | O_CLOEXEC);
    setns(target, CLONE_NEWNET);
    auto result = fn();
    setns(self, CLONE_NEWNET);
    close(target);
    close(self);
    return result;
  }

 private:
  bool Ip(const std::vector<std::string>& args);
  bool WaitForCarrier() const;  // both ends of the veth pair up, with carrier
  std::string ns_[2], if_[2], ip_[2];
  bool created_[2] = {false, false};
  std::string error_;
};

}  // namespace turf::test
