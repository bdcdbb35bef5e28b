#include "participants/launcher/log_command.h"

#include <cstdio>
#include <set>

#include "participants/common/mcap_file.h"
#include "participants/launcher/log_diff.h"
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
  diff_ = log->add_subcommand("diff",
                              "compare two recordings sample by sample, byte for byte (topics matched without their "
                              "prefix) and name the earliest difference");
  diff_->add_option("a", file_, "the first MCAP file")->required();
  diff_->add_option("b", other_, "the second MCAP file")->required();
  diff_->add_option("--skip", skip_,
                    "topics to leave out, without prefix (e.g. clock, whose run epoch and measured speed differ "
                    "between runs); repeatable");
  diff_->add_option("--until", until_s_, "compare only samples up to this simulation time (s)")
      ->check(CLI::Range(0.0, 1e9));
}

int LogCommand::Run() { return diff_->parsed() ? RunDiff() : RunInfo(); }

int LogCommand::RunDiff() {
  McapFileSource a(file_), b(other_);
  for (const McapFileSource* s : {&a, &b}) {
    if (!s->ok()) {
      std::fprintf(stderr, "turf log diff: %s\n", s->error().c_str());
      return 2;
    }
  }
  DiffOptions options;
  options.skip.insert(skip_.begin(), skip_.end());
  if (until_s_ >= 0) options.until_ns = static_cast<uint64_t>(until_s_ * 1e9);
  const LogDiff diff = DiffRecordings(a, b, options);
  for (const mcap::Damage* d : {&diff.damage_a, &diff.damage_b}) {
    if (d->error == mcap::ReadError::kBadMagic || d->error == mcap::ReadError::kNewerVersion) {
      std::fprintf(stderr, "turf log diff: %s\n", d->Describe().c_str());
      return 2;
    }
  }
  std::fputs(diff.report.c_str(), stdout);
  return diff.same ? 0 : 1;
}

int LogCommand::RunInfo() {
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
