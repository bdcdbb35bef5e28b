#include "participants/launcher/log_command.h"

#include <cstdio>

#include "participants/common/mcap_file.h"
#include "participants/launcher/log_info.h"

namespace turf::launch {

LogCommand::LogCommand(CLI::App& app) {
  CLI::App* log = app.add_subcommand("log", "MCAP recordings of matches (turf-record's)");
  log->require_subcommand(1);
  info_ = log->add_subcommand("info",
                              "duration, simulation time, chunks and compression, and per channel the topic, "
                              "messages, rate, bytes and schema of an MCAP file; a damaged file is read up to the "
                              "damage, which is named with its offset");
  info_->add_option("file", file_, "the MCAP file")->required();
}

int LogCommand::Run() {
  McapFileSource source(file_);
  if (!source.ok()) {
    std::fprintf(stderr, "turf log info: %s\n", source.error().c_str());
    return 2;
  }
  const LogInfo info = ReadLogInfo(file_, source);
  const mcap::ReadError e = info.scan.error;
  if (e == mcap::ReadError::kBadMagic || e == mcap::ReadError::kNewerVersion) {
    std::fprintf(stderr, "turf log info: %s: %s\n", file_.c_str(), info.scan.Describe().c_str());
    return 2;
  }
  std::fputs(FormatLogInfo(info).c_str(), stdout);
  if (!info.scan.ok()) std::fprintf(stderr, "turf log info: %s: %s\n", file_.c_str(), info.scan.Describe().c_str());
  return info.scan.ok() ? 0 : 1;
}

}  // namespace turf::launch
