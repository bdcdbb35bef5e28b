// libFuzzer target for the viewer's HTTP rules (request targets and headers come from anyone reaching the web
// port): StaticFile never names a file outside the web root (only [A-Za-z0-9._-] segments, none starting with '.',
// at most 4 deep and 200 bytes), ParseCameraTarget only gives valid names, and no input crashes or trips a
// sanitizer. The bytes are split at the first NUL into a target (or Host) and an Origin.
#include <algorithm>
#include <cctype>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "participants/viewer/http_rules.h"

namespace {

bool InsideWebRoot(const std::string& path) {
  if (path.empty() || path.size() > 200) return false;
  int segments = 0;
  size_t start = 0;
  while (start <= path.size()) {
    const size_t end = std::min(path.find('/', start), path.size());
    const std::string_view segment(path.data() + start, end - start);
    if (segment.empty() || segment[0] == '.') return false;
    for (char c : segment)
      if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '_' && c != '-') return false;
    ++segments;
    start = end + 1;
  }
  return segments <= 4;
}

// A camera panel name: [A-Za-z0-9_], 1..64 bytes.
bool Name(const std::string& s) {
  if (s.empty() || s.size() > 64) return false;
  for (char c : s)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') return false;
  return true;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view all(reinterpret_cast<const char*>(data), size);
  const std::string_view first = all.substr(0, all.find('\0'));
  const std::string_view rest = first.size() < all.size() ? all.substr(first.size() + 1) : std::string_view();
  if (const std::optional<std::string> file = turf::viewer::StaticFile(first)) {
    if (!InsideWebRoot(*file)) std::abort();
    (void)turf::viewer::ContentType(*file);
  }
  if (const std::optional<turf::viewer::CameraTarget> camera = turf::viewer::ParseCameraTarget(first)) {
    if (!Name(camera->robot) || !Name(camera->camera)) std::abort();
  }
  (void)turf::viewer::UpgradeAllowed(first, rest, true);
  (void)turf::viewer::UpgradeAllowed(first, rest, false);
  return 0;
}
