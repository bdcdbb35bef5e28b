#include "participants/render/camera_switch.h"

#include <fmt/format.h>

#include <cmath>

namespace turf {

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
  if (!std::isfinite(r.rate_hz) || r.rate_hz < 0 || r.rate_hz > kMaxCameraRateHz) {
    *why = fmt::format("rate_hz {} is not in [0, {}]", r.rate_hz, kMaxCameraRateHz);
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
