// Which of turf-render's cameras are on, and at what rate: each starts as the scene (or --cameras) says, and a
// control sample (<prefix>/cameras/control, idl/ros/CameraControl.idl) switches one on or off at run time, at the
// scene's rate or another. Pure state, no DDS: the node feeds it the samples it reads. A sample naming a camera
// not in this renderer's set is another renderer's (not an error); a rate that is not finite, negative or above
// kMaxCameraRateHz is refused, and nothing changes.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "core/camera/camera_model.h"

namespace turf {

struct CameraControlRequest {
  std::string robot;
  std::string camera;
  bool enabled = false;
  double rate_hz = 0;  // 0: the declared rate
  std::string source;  // who asks (logs)
};

// A command line's switch, "red_1/camera=on", "red_1/camera=on@62.5" (Hz of sim time) or "red_1/camera=off"; nullopt
// (with `why`) for anything else, a rate as CameraSwitch refuses it included.
std::optional<CameraControlRequest> ParseCameraSwitch(const std::string& text, std::string* why);

class CameraSwitch {
 public:
  enum class Outcome { kChanged, kUnchanged, kNotMine, kRefused };

  explicit CameraSwitch(const std::vector<CameraSpec>& cameras);

  // Applies `request`; for kRefused `why` says what was wrong.
  Outcome Apply(const CameraControlRequest& request, std::string* why);
  // The camera a request names, or size() if none.
  size_t Find(const std::string& robot, const std::string& camera) const;

  size_t size() const { return cameras_.size(); }
  bool enabled(size_t i) const { return cameras_[i].enabled; }
  double rate_hz(size_t i) const { return cameras_[i].rate_hz; }
  size_t enabled_count() const;

 private:
  struct State {
    std::string robot, camera;
    double declared_rate_hz = 0;
    bool enabled = false;
    double rate_hz = 0;
  };
  std::vector<State> cameras_;
};

}  // namespace turf
