#include "participants/launcher/security_command.h"

#include <cstdio>
#include <string>

#include "dds/security_policy.h"

namespace turf::launch {

SecurityCommand::SecurityCommand(CLI::App& app) {
  CLI::App* security = app.add_subcommand("security", "DDS Security for a match: per-team identities and permissions");
  security->require_subcommand(1);
  std::string names;
  for (const std::string& name : dds::IdentityNames()) names += (names.empty() ? "" : ", ") + name;
  init_ = security->add_subcommand("init", "make a CA, a signed governance and, per identity (" + names +
                                               "), a key, a certificate and signed permissions in DIR/<identity>; "
                                               "each participant then takes --security DIR/<identity>");
  init_->add_option("dir", options_.dir, "directory to make (must not hold a CA yet)")->required();
  init_->add_option("-p,--prefix", options_.prefix, "topic prefix the permissions name")->capture_default_str();
  init_->add_flag("--tournament", tournament_,
                  "teams may neither read the world state (ground truth) nor send control requests (pause, teleport); "
                  "default: the lab profile, where they may");
  init_->add_flag("--no-encryption", no_encryption_,
                  "authentication and access control only, nothing encrypted (to measure what encryption costs)");
  init_->add_option("--days", options_.days, "days the certificates and permissions are valid")
      ->capture_default_str()
      ->check(CLI::Range(1, 36500));
}

int SecurityCommand::Run() {
  if (tournament_) options_.profile = dds::SecurityProfile::kTournament;
  if (no_encryption_) options_.protection = dds::Protection::kNone;
  const std::vector<std::string> errors = InitSecurity(options_);
  for (const std::string& e : errors) std::fprintf(stderr, "turf security init: %s\n", e.c_str());
  if (!errors.empty()) return 2;
  std::printf("made a CA and %zu identities in %s (%s profile, %s); give each participant --security %s/<identity>\n",
              dds::IdentityNames().size(), options_.dir.c_str(), tournament_ ? "tournament" : "lab",
              no_encryption_ ? "not encrypted" : "encrypted", options_.dir.c_str());
  return 0;
}

}  // namespace turf::launch
