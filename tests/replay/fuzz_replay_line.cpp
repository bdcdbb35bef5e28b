// libFuzzer: turf-replay's terminal command parser never crashes and refuses or parses every line.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>
#include <variant>

#include "participants/replay/replay_keys.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const auto result = turf::ParseReplayLine(std::string_view(reinterpret_cast<const char*>(data), size));
  if (const auto* command = std::get_if<turf::ReplayCommand>(&result)) {
    if (command->seek_time_ns < 0 || command->speed < 0) std::abort();
  } else if (std::get<turf::ReplayRefusal>(result).reason.empty()) {
    std::abort();
  }
  return 0;
}
