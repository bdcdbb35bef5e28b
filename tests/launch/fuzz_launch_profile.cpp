// libFuzzer target for the launch profile reader (`turf launch <profile>`: profiles are files from outside): any
// bytes give a profile or errors, never both, never neither, and never a crash, a sanitizer report or an exception.
// Relative paths in the text resolve against the shipped profiles' directory.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "participants/launcher/launch_profile.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const turf::launch::ProfileLoadResult r = turf::launch::ParseLaunchProfile(text, turf::launch::DefaultProfileDir());
  if (r.profile.has_value() == !r.errors.empty()) std::abort();
  return 0;
}
