// Shared by the viewer's JSON writers (viewer_json.cpp, legged_json.cpp):
// rounding, times, and a dump that survives invalid UTF-8.
#pragma once

#include <turf/idl/Clock.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdint>
#include <string>

namespace turf::viewer::json_util {

// Rounded so that the shortest decimal form is short; non-finite values never
// get here (ViewerModel refuses such samples), but would become 0, not null.
inline double R(double v, double scale = 1e4) { return std::isfinite(v) ? std::round(v * scale) / scale : 0.0; }
inline double Ns(int64_t ns) { return R(static_cast<double>(ns) * 1e-9, 1e6); }

// Strings from DDS or the command line may hold invalid UTF-8, which a plain
// dump() throws on: replace such bytes instead.
inline std::string Dump(const nlohmann::json& j) {
  return j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

}  // namespace turf::viewer::json_util
