// `turf log info FILE`: what an MCAP recording (turf-record's) holds (log_info.h). Exit status 0 when the file
// reads to its end, 1 when it is damaged (what it holds up to the damage is still printed), 2 when it cannot be
// opened or is no MCAP file of a version this build reads. `turf log diff A B` compares two recordings sample by
// sample (log_diff.h): exit status 0 when they hold the same samples, 1 when they differ, 2 when one cannot be read.
#pragma once

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

#include "core/pinned.h"

namespace turf::launch {

class LogCommand : Pinned {
 public:
  explicit LogCommand(CLI::App& app);
  bool Chosen() const { return info_->parsed() || diff_->parsed(); }
  int Run();

 private:
  int RunInfo();
  int RunDiff();

  CLI::App* info_ = nullptr;
  CLI::App* diff_ = nullptr;
  std::string file_;
  std::string other_;
  std::vector<std::string> skip_;
  double until_s_ = -1;
};

}  // namespace turf::launch
