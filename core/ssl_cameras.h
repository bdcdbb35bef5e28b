// SSL-Vision-like cameras: where they hang, which part of the field each one
// reports, and what each reports of a captured frame, through the camera's
// value model (occlusion, vanishing, noise, confidence) and its link
// (processing delay, latency, jitter, loss). With ideal realism a frame is
// exact and released at its capture time.
#pragma once

#include <cstdint>
#include <deque>
#include <vector>

#include "core/link_model.h"
#include "core/rng.h"
#include "core/scene.h"
#include "core/sensor_realism.h"
#include "core/stream_stats.h"
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
  uint64_t frame_number = 0;  // per camera, from 1; a lost frame leaves a gap
  int64_t capture_time_ns = 0;
  int64_t sent_time_ns = 0;  // left the vision system (capture + processing)
  std::vector<DetectedBall> balls;
  std::vector<DetectedRobot> robots;
};

// Where a camera reports the ball: SSL-Vision finds its blob in the image and projects it onto the plane of a ball
// on the carpet (its centre's height, `ball_radius`), so a ball in the air is reported where the ray from the
// camera through it meets that plane, further from the camera than it is, and at that plane's height (as real
// vision does, and grSim and ER-Force's simulator model). A ball on the carpet is reported where it is.
Vec3 SeenBallPosition(const Vec3& camera, const Vec3& ball, double ball_radius);

// What one camera reports of a world snapshot, exactly (the ball as SeenBallPosition).
CameraFrame Detect(const CameraSpec& camera, const WorldSnapshot& world, double robot_height, double ball_radius);

// True if a robot stands between the camera and the ball's centre.
bool BallOccluded(const CameraSpec& camera, const Vec3& ball, const WorldSnapshot& world, double robot_radius,
                  double robot_height);

// The camera's value model applied to its exact frame, drawing from `rng`.
void ApplyValueModel(const CameraSpec& camera, const CameraRealism& realism, const WorldSnapshot& world,
                     const RobotParams& robot, Rng& rng, CameraFrame* frame);

// Captures all cameras together at the scene's camera rate (simulation time)
// and releases each frame when its modelled arrival time has come.
class SslCameraSystem {
 public:
  explicit SslCameraSystem(const Scene& scene);
  const std::vector<CameraSpec>& cameras() const { return cameras_; }
  void SetRealism(const CameraRealism& realism);
  const CameraRealism& realism() const { return realism_; }
  // True when a capture falls due at `time_ns` (the first step at or after the
  // scheduled exposure). The first exposure ends one frame period after the
  // start, so no frame is ever stamped with time 0.
  bool Due(int64_t time_ns) const { return time_ns >= next_capture_ns_; }
  // Captures every camera and schedules the next capture.
  void Capture(const WorldSnapshot& world);
  // Moves the frames that have arrived by `now_ns` into `out` (cleared first),
  // oldest first.
  void Release(int64_t now_ns, std::vector<CameraFrame>* out);
  // What each camera's stream achieved since the last call (sent = captured).
  StreamWindow TakeStats(int camera) { return streams_[camera].stats.Take(); }
  void Reset();
  // Realism, random streams, links, statistics and frames in flight.
  void Save(StateWriter& out) const;
  void Restore(StateReader& in);

 private:
  struct Stream {
    Rng values;
    Link link;
    StreamStats stats;
  };
  struct Pending {
    int64_t arrival_ns;
    CameraFrame frame;
    template <class Io>
    friend void Fields(Io& io, IoRef<Io, Pending> p) {
      io(p.arrival_ns, p.frame);
    }
  };

  template <class Io, class Self>
  static void Fields(Io& io, Self& self);

  Scene scene_;
  std::vector<CameraSpec> cameras_;
  CameraRealism realism_;
  std::vector<Stream> streams_;
  std::deque<Pending> pending_;  // ordered by arrival
  double period_ns_ = 0.0;
  uint64_t captures_ = 0;
  int64_t next_capture_ns_ = 0;  // set by Reset()
};

}  // namespace turf
