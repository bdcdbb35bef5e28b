// What every turf participant is told on its command line: which DDS domain
// and topic prefix to join, with which QoS profiles, under which name. Each
// participant's options struct derives from it and sets its own name.
//
// The same four fields as dds::ParticipantOptions (dds/participant.h), kept
// apart so that option headers stay free of Fast DDS; the nodes copy them over.
#pragma once

#include <string>

namespace turf {

struct ParticipantOptions {
  int domain = 0;               // -d, --domain: 0..232
  std::string prefix = "turf";  // -p, --prefix: topic names are <prefix>/<suffix>
  std::string qos_file;         // --qos: Fast DDS XML profiles; empty: the shipped ones
  std::string name = "turf";    // the DDS participant's name (the process's, e.g. "turf-sim")
};

}  // namespace turf
