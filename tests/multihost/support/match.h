// turf-sim and the SSL bridges as real processes for the multi-host, fault
// and launch tests, each optionally inside a network namespace (TwoHosts).
// grSim and vision traffic stays on 127.0.0.1 of the bridge host: unicast.
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "tests/multihost/support/netns.h"
#include "tests/support/process.h"

namespace turf::test {

struct MatchSetup {
  int domain = 0;
  std::string prefix;
  const TwoHosts* hosts = nullptr;  // nullptr: everything on this host's loopback
  Process::Env env;                 // for every participant, e.g. ROS_DISCOVERY_SERVER
  std::string scene = "ssl_div_a";  // configs/scenes/<scene>.yaml
  std::string security;             // a `turf security init` directory: each process runs as its identity; "": off
};

class Match {
 public:
  explicit Match(MatchSetup setup);
  // Each start gives a new process (a restart is just another start); the
  // log file is named after the process and `tag`.
  std::unique_ptr<Process> Sim(const std::string& tag = "") const;
  std::unique_ptr<Process> Grsim(const std::string& tag = "") const;
  std::unique_ptr<Process> Vision(const std::string& tag = "") const;

  int grsim_port = 0;   // on 127.0.0.1 of the bridge host
  int vision_port = 0;  // detections and geometry go to 127.0.0.1:vision_port

 private:
  std::unique_ptr<Process> Start(const std::string& name, const std::string& binary, std::vector<std::string> args,
                                 bool bridge_host, const std::string& identity) const;
  MatchSetup setup_;
};

}  // namespace turf::test
