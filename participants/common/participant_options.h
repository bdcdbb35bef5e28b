// What every turf participant is told on its command line: which DDS domain
// and topic prefix to join, with which QoS profiles, under which name. Each
// participant's options struct derives from it and sets its own name.
//
// The same fields as dds::ParticipantOptions (dds/participant.h, which needs no
// Fast DDS headers either); DdsOptions() is the one conversion.
#pragma once

#include <chrono>
#include <cstdint>
#include <string>

#include "dds/participant.h"

namespace turf {

struct ParticipantOptions {
  int domain = 0;                          // -d, --domain: 0..232
  std::string prefix = "turf";             // -p, --prefix: topic names are <prefix>/<suffix>
  std::string qos_file;                    // --qos: Fast DDS XML profiles; empty: the shipped ones
  std::string name = "turf";               // the DDS participant's name (the process's, e.g. "turf-sim")
  std::string security;                    // --security: an identity directory of `turf security init`; empty: off
  double authentication_timeout_s = 20.0;  // --authentication-timeout: dds::ParticipantOptions::authentication_timeout

  std::chrono::milliseconds authentication_timeout() const {
    return std::chrono::milliseconds(static_cast<int64_t>(authentication_timeout_s * 1000.0));
  }
};

// The DDS participant these options describe; `name`, if given, replaces theirs (a second participant of one
// process, such as a writer watch).
inline dds::ParticipantOptions DdsOptions(const ParticipantOptions& o, const std::string& name = "") {
  return {o.domain, name.empty() ? o.name : name, o.prefix, o.qos_file, o.security, o.authentication_timeout()};
}

}  // namespace turf
