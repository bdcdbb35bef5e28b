// Where the HLVS session gets camera images: an interface, so a renderer (turf-render's image topics, issue 16:
// participants/hlvs_bridge/dds_camera_source.h) slots in without touching the session. With no source, or a source that
// has no image yet, an enabled camera is simply not in the SensorMeasurements (the session says so once:
// HlvsSession::camera_unavailable()).
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "codecs/hlvs/wire.h"

namespace turf::hlvs {

struct CameraRequest {
  std::string robot;   // the scene's robot name
  std::string camera;  // the robot file's MJCF camera
  uint32_t width = 0, height = 0;
  double exposure = 0;       // J/m^2 as the client set it (0: never set)
  uint64_t sim_time_ms = 0;  // the measurement's time: the image should show the state at or just before it
};

class CameraSource {
 public:
  virtual ~CameraSource() = default;
  // An image of width * height * 3 bytes in HLVS byte order (B, G, R; rows from the top), name and quality left to
  // the caller; nullopt when none is available. Called on the bridge's step: it must not wait for an image.
  virtual std::optional<CameraImage> Take(const CameraRequest& request) = 0;
  // A client switched a camera on with period `period_ms` of simulated time (a renderer should draw it at that
  // period), or off (0). The session calls it only when the period changes.
  virtual void Enable(const std::string& robot, const std::string& camera, uint32_t period_ms) {
    (void)robot, (void)camera, (void)period_ms;
  }
  // The bridge attached: its time 0 (CameraRequest::sim_time_ms) is turf-sim's `sim_time_ns` (the renderer's stamps).
  virtual void Attached(int64_t sim_time_ns) { (void)sim_time_ns; }
};

}  // namespace turf::hlvs
