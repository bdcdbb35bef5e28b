// HLVS camera images from turf-render's topics (issue 16): a hlvs::CameraSource over DDS. When a client switches a
// robot's camera on (Enable), it asks turf-render for it on <prefix>/cameras/control at the client's period
// (re-sent every second while on, so a renderer started later or restarted picks it up; switched off again when
// the client sets 0 or the bridge stops) and subscribes to its rt/<prefix>/<robot>/<camera>/image_raw. Frames are
// converted to HLVS's B, G, R bytes on Fast DDS's thread as they arrive (camera_feed.h), so Take, on the bridge's
// step, only moves a ready frame out: the newest at or before the measurement's time not sent before, or nothing.
// It never waits: a frame that is not there yet is simply not in that message (counted: missed()).
//
// Reads:  rt/<prefix>/<robot>/<camera>/image_raw (sensor_msgs::msg::dds_::Image_, rgb8 or yuv422_yuy2)
// Writes: <prefix>/cameras/control (turf::idl::CameraControl)
// The images on a participant of its own for large samples (dds::VendorParticipant), as turf-render's; the switch
// on another, without (written synchronously, so the last "off" is sent before the bridge exits).
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "codecs/hlvs/camera_source.h"

namespace turf {

struct CameraSourceOptions {
  int domain = 0;
  std::string prefix = "turf";
  std::string security;  // an identity directory, as the bridge's own
  std::string name = "turf-hlvs-bridge";
};

struct CameraSourceStats {
  uint64_t frames = 0;    // frames received and kept
  uint64_t refused = 0;   // frames refused (sizes, encoding)
  uint64_t sent = 0;      // frames given to a client
  uint64_t missed = 0;    // a camera was due and no new frame was there
  uint64_t controls = 0;  // control samples written
};

class DdsCameraSource final : public hlvs::CameraSource {
 public:
  explicit DdsCameraSource(CameraSourceOptions options);
  ~DdsCameraSource() override;  // switches every camera it switched on off again

  std::optional<hlvs::CameraImage> Take(const hlvs::CameraRequest& request) override;
  void Enable(const std::string& robot, const std::string& camera, uint32_t period_ms) override;
  void Attached(int64_t sim_time_ns) override;

  CameraSourceStats Stats() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace turf
