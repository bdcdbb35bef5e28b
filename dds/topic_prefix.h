// The one rule for a topic prefix (-p/--prefix of every participant, a launch
// profile's `prefix`, turf.Sim.publish's prefix): topic names are
// <prefix>/<suffix>, so a prefix is one or more of letters, digits, '_', '-' and
// '/'. No spaces, and none of the '*', '?' and '[' that DDS Security's topic
// expressions would read as patterns.
#pragma once

#include <algorithm>
#include <cctype>
#include <string>

namespace turf::dds {

inline constexpr const char* kTopicPrefixRule = "letters, digits, '_', '-' and '/' only, not empty";

inline bool ValidTopicPrefix(const std::string& prefix) {
  return !prefix.empty() && std::all_of(prefix.begin(), prefix.end(), [](unsigned char c) {
    return std::isalnum(c) || c == '_' || c == '/' || c == '-';
  });
}

}  // namespace turf::dds
