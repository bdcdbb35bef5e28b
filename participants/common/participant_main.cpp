#include "participants/common/participant_main.h"

#include "participants/common/cli_checks.h"

#include <spdlog/spdlog.h>

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <stdexcept>
#include <utility>

#include "dds/topic_prefix.h"
#include "participants/common/process.h"

namespace turf {

// The stop signals first: a stop asked while the flags are declared and parsed (a launcher stopping what it has just
// started) is the body's first StopRequested(), not a death by the signal's default action.
ParticipantMain::ParticipantMain(std::string process_name, const std::string& description)
    : process_name_(std::move(process_name)), app_(description) {
  InstallStopSignals();
}

ParticipantMain::ParticipantMain(const std::string& description)
    : ParticipantMain(description.substr(0, description.find(':')), description) {}

void ParticipantMain::AddCommonFlags(ParticipantOptions& options, const CommonFlagHelp& help) {
  app_.add_option("-d,--domain", options.domain, help.domain)->capture_default_str()->check(CLI::Range(0, 232));
  app_.add_option("-p,--prefix", options.prefix, help.prefix)
      ->capture_default_str()
      ->check([](const std::string& prefix) { return dds::ValidTopicPrefix(prefix) ? "" : dds::kTopicPrefixRule; });
  app_.add_option("--qos", options.qos_file, "Fast DDS XML QoS profiles (default: configs/qos/turf_qos.xml)")
      ->check(CLI::ExistingFile);  // a missing file is a configuration error (exit 2), told before anything starts
  app_.add_option("--security", options.security,
                  "DDS Security: this participant's identity directory, DIR/<identity> of `turf security init DIR` "
                  "(authenticated, only what its signed permissions allow, encrypted); default: off")
      ->type_name("DIR")
      ->check(CLI::ExistingDirectory);
  app_.add_option(
          "--authentication-timeout", options.authentication_timeout_s,
          "with --security: s after which a participant discovered that has not finished authenticating is "
          "named in a warning; a bridge still waiting for turf-sim then restarts itself (README, Access control)")
      ->capture_default_str()
      ->check(CLI::Range(0.5, 3600.0));
}

CLI::Option* ParticipantMain::AddPort(const std::string& name, uint16_t& port, const std::string& help,
                                      bool zero_allowed) {
  return AddPortOption(app_, name, port, help, zero_allowed);
}

int ParticipantMain::Run(int argc, const char* const* argv, const std::function<int()>& body) {
  app_.add_option("--log-level", log_level_, "trace, debug, info, warn, error")->capture_default_str();
  try {
    app_.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // Prints the help (stdout) or what was wrong (stderr); 0 only for --help.
    return app_.exit(e) == 0 ? kExitClean : kExitBadConfig;
  }
  if (!SetupLogging(process_name_, log_level_)) return kExitBadConfig;
  int code = kExitFailure;
  try {
    code = body();
  } catch (const std::invalid_argument& e) {
    spdlog::error("{}", e.what());
    return kExitBadConfig;
  } catch (const std::exception& e) {
    spdlog::critical("{}", e.what());
    return kExitFailure;
  } catch (...) {
    spdlog::critical("stopped by an exception that is not a std::exception");
    return kExitFailure;
  }
  if (code == kExitClean && RestartRequested()) return Restart(argv);
  if (code == kExitClean) spdlog::info("stopped cleanly");
  return code;
}

// Everything the body made is gone (its sockets closed, its DDS participant deleted): the same program starts again
// in this process, with the same arguments.
int ParticipantMain::Restart(const char* const* argv) {
  spdlog::info("stopped cleanly; starting again with the same arguments");
  spdlog::default_logger()->flush();
  std::fflush(nullptr);
  execv("/proc/self/exe", const_cast<char* const*>(argv));
  spdlog::critical("could not start again: execv /proc/self/exe: {}", std::strerror(errno));
  return kExitFailure;
}

}  // namespace turf
