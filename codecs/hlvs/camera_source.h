// Where the HLVS session gets camera images: an interface, so a renderer (turf-render's image topics, issue 16)
// slots in without touching the session. With no source, or a source that has no image yet, an enabled camera is
// simply not in the SensorMeasurements (the session says so once: HlvsSession::camera_unavailable()).
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
  // the caller; nullopt when none is available.
  virtual std::optional<CameraImage> Take(const CameraRequest& request) = 0;
};

}  // namespace turf::hlvs
