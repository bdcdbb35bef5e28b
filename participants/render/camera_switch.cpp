#include "participants/render/camera_switch.h"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>

namespace turf {

std::optional<CameraControlRequest> ParseCameraSwitch(const std::string& text, std::string* why) {
  const size_t slash = text.find('/'), eq = text.find('=');
  if (slash == std::string::npos || eq == std::string::npos || slash == 0 || eq < slash + 2) {
    *why = "'" + text + "': expected ROBOT/CAMERA=on, ROBOT/CAMERA=on@HZ or ROBOT/CAMERA=off";
    return std::nullopt;
  }
  CameraControlRequest r;
  r.robot = text.substr(0, slash);
  r.camera = text.substr(slash + 1, eq - slash - 1);
  const std::string state = text.substr(eq + 1);
  if (state == "off") return r;
  if (state.rfind("on", 0) != 0 || (state.size() > 2 && state[2] != '@')) {
    *why = "'" + text + "': the state is on, on@HZ or off";
    return std::nullopt;
  }
  r.enabled = true;
  if (state.size() > 2) {
    char* end = nullptr;
    r.rate_hz = std::strtod(state.c_str() + 3, &end);
    if (end == state.c_str() + 3 || *end != '\0' || !std::isfinite(r.rate_hz) || r.rate_hz < kMinCameraRateHz ||
        r.rate_hz > kMaxCameraRateHz) {
      *why = fmt::format("'{}': the rate is a number of Hz in [{}, {}]", text, kMinCameraRateHz, kMaxCameraRateHz);
      return std::nullopt;
    }
  }
  return r;
}

CameraSwitch::CameraSwitch(const std::vector<CameraSpec>& cameras) {
  for (const CameraSpec& c : cameras) cameras_.push_back({c.robot, c.name, c.rate_hz, c.enabled, c.rate_hz});
}

size_t CameraSwitch::Find(const std::string& robot, const std::string& camera) const {
  for (size_t i = 0; i < cameras_.size(); ++i)
    if (cameras_[i].robot == robot && cameras_[i].camera == camera) return i;
  return cameras_.size();
}

CameraSwitch::Outcome CameraSwitch::Apply(const CameraControlRequest& r, std::string* why) {
  const size_t i = Find(r.robot, r.camera);
  if (i == cameras_.size()) return Outcome::kNotMine;
  if (!std::isfinite(r.rate_hz) || r.rate_hz < 0 || (r.rate_hz > 0 && r.rate_hz < kMinCameraRateHz) ||
      r.rate_hz > kMaxCameraRateHz) {
    *why = fmt::format("rate_hz {} is neither 0 (the scene's rate) nor in [{}, {}]", r.rate_hz, kMinCameraRateHz,
                       kMaxCameraRateHz);
    return Outcome::kRefused;
  }
  State& s = cameras_[i];
  const double rate = r.rate_hz > 0 ? r.rate_hz : s.declared_rate_hz;
  if (s.enabled == r.enabled && (!r.enabled || s.rate_hz == rate)) return Outcome::kUnchanged;
  s.enabled = r.enabled;
  if (r.enabled) s.rate_hz = rate;
  return Outcome::kChanged;
}

size_t CameraSwitch::enabled_count() const {
  size_t n = 0;
  for (const State& s : cameras_) n += s.enabled;
  return n;
}

}  // namespace turf
