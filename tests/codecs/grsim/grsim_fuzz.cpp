// libFuzzer target for the grSim command codec: any bytes decode to a result
// or a named error, without a crash, a sanitizer report or a bad command.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>

#include "codecs/grsim/grsim_codec.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  turf::grsim::GrsimCodecConfig config;
  config.robots_per_team = 11;
  const turf::grsim::GrsimDecodeResult r = turf::grsim::Decode(data, size, config);
  if (!r.ok() && (!r.requests.commands.empty() || !r.requests.controls.empty())) std::abort();
  for (const turf::idl::SslRobotCommand& c : r.requests.commands) {
    // What the codec passes on is within turf-sim's sanity limits.
    if (c.id() >= 11 || !std::isfinite(c.kick_speed()) || c.kick_speed() < 0 || c.kick_speed() > 30) std::abort();
    if (!(c.chip_angle() >= 0 && c.chip_angle() < M_PI / 2)) std::abort();
    if (std::hypot(c.velocity().x(), c.velocity().y()) > 20 || std::abs(c.velocity().z()) > 100) std::abort();
    for (double w : c.wheel_velocity())
      if (!(std::abs(w) <= 20)) std::abort();
  }
  for (const turf::idl::SimControl& c : r.requests.controls) {
    if (!std::isfinite(c.robot().orientation()) || !std::isfinite(c.ball().position().x())) std::abort();
  }
  return 0;
}
