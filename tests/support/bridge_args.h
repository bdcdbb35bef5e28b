// Command lines of turf's bridges as tests start them.
#pragma once

#include <string>
#include <vector>

#include "tests/support/process.h"

namespace turf::test {

// turf-simproto-bridge on 127.0.0.1 with only its control port open, then `more` (the DDS domain and prefix).
inline std::vector<std::string> SimprotoControlOnly(int control_port, const std::vector<std::string>& more) {
  std::vector<std::string> args = {Built("participants/simproto_bridge/turf-simproto-bridge"),
                                   "--listen",
                                   "127.0.0.1",
                                   "--control-port",
                                   std::to_string(control_port),
                                   "--blue-port",
                                   "0",
                                   "--yellow-port",
                                   "0",
                                   "--sync-port",
                                   "0"};
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

}  // namespace turf::test
