// `turf security init DIR`: its flags and what it does with them (security_init.h makes the files).
#pragma once

#include <CLI/CLI.hpp>

#include "core/pinned.h"
#include "participants/launcher/security_init.h"

namespace turf::launch {

class SecurityCommand : Pinned {
 public:
  // Adds `security` and its `init` subcommand to `app`, which must outlive this object.
  explicit SecurityCommand(CLI::App& app);
  bool Chosen() const { return init_->parsed(); }
  // 0 when every file was made; 2 (printed on stderr) otherwise.
  int Run();

 private:
  CLI::App* init_ = nullptr;
  SecurityInitOptions options_;
  bool tournament_ = false;
  bool no_encryption_ = false;
};

}  // namespace turf::launch
