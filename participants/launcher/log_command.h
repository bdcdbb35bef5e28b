// `turf log info FILE`: what an MCAP recording (turf-record's) holds (log_info.h). Exit status 0 when the file
// reads to its end, 1 when it is damaged (what it holds up to the damage is still printed), 2 when it cannot be
// opened or is no MCAP file of a version this build reads.
#pragma once

#include <CLI/CLI.hpp>

#include <string>

#include "core/pinned.h"

namespace turf::launch {

class LogCommand : Pinned {
 public:
  explicit LogCommand(CLI::App& app);
  bool Chosen() const { return info_->parsed(); }
  int Run();

 private:
  CLI::App* info_ = nullptr;
  std::string file_;
};

}  // namespace turf::launch
