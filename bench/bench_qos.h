// For benchmarks that put two participants in one process: the shipped QoS file with Fast DDS's intra-process
// shortcut switched off, so samples take the transport two processes would. Written to /tmp; returns its path.
#pragma once

#include <unistd.h>

#include <fstream>
#include <sstream>
#include <string>

#include "dds/participant.h"

namespace turf::bench {

inline std::string QosWithoutIntraprocess(const std::string& name) {
  std::ifstream in(turf::dds::DefaultQosFile());
  std::stringstream text;
  text << in.rdbuf();
  std::string xml = text.str();
  const std::string anchor = "<profiles>";
  xml.insert(xml.find(anchor),
             "<library_settings><intraprocess_delivery>OFF</intraprocess_delivery></library_settings>\n  ");
  const std::string path = "/tmp/turf_bench_" + name + "_qos_" + std::to_string(getpid()) + ".xml";
  std::ofstream(path) << xml;
  return path;
}

}  // namespace turf::bench
