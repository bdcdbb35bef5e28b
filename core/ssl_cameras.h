// SSL-Vision-like cameras: where they hang, which part of the field each one
// reports, and what each reports in a captured frame. Ideal for now: exact
// positions, every object in the camera's area, capture and send at once.
#pragma once

#include <cstdint>
#include <vector>

#include "core/scene.h"
#include "core/types.h"
#include "core/world.h"

namespace turf {

struct CameraSpec {
  int id = 0;
  Vec3 position;                                              // optical centre, field frame
  double min_x = 0.0, max_x = 0.0, min_y = 0.0, max_y = 0.0;  // reported area
};

// Division A: four cameras, one per quadrant (ids counter-clockwise from
// +x+y); division B: two, one per half (id 0 at -x). Neighbouring areas share
// a strip `overlap` wide; every area reaches the walls.
std::vector<CameraSpec> CameraLayout(const Scene& scene);

struct DetectedBall {
  Vec3 position;
  float confidence = 1.0f;
};

struct DetectedRobot {
  Team team = Team::kBlue;
  int id = 0;
  double x = 0.0;
  double y = 0.0;
  double orientation = 0.0;
  double height = 0.0;
  float confidence = 1.0f;
};

struct CameraFrame {
  int camera_id = 0;
  uint64_t frame_number = 0;  // per camera, from 1
  int64_t capture_time_ns = 0;
  int64_t sent_time_ns = 0;
  std::vector<DetectedBall> balls;
  std::vector<DetectedRobot> robots;
};

// What one camera reports of a world snapshot.
CameraFrame Detect(const CameraSpec& camera, const WorldSnapshot& world, double robot_height);

// Captures all cameras together at the scene's camera rate, in simulation time.
class SslCameraSystem {
 public:
  explicit SslCameraSystem(const Scene& scene);
  const std::vector<CameraSpec>& cameras() const { return cameras_; }
  // True when a capture falls due at `time_ns` (the first step at or after the
  // scheduled exposure). The first exposure ends one frame period after the
  // start, so no frame is ever stamped with time 0.
  bool Due(int64_t time_ns) const { return time_ns >= next_capture_ns_; }
  // Captures every camera into `out` (cleared first) and schedules the next.
  void Capture(const WorldSnapshot& world, std::vector<CameraFrame>* out);
  void Reset();

 private:
  std::vector<CameraSpec> cameras_;
  double robot_height_ = 0.0;
  double period_ns_ = 0.0;
  uint64_t captures_ = 0;
  int64_t next_capture_ns_ = 0;  // set by Reset()
};

}  // namespace turf
