#include "core/ssl_cameras.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/state_fields.h"

namespace turf {

std::vector<CameraSpec> CameraLayout(const Scene& scene) {
  const FieldParams& f = scene.field;
  const double x_in = f.length / 2 + f.boundary_width_goal_line;
  const double y_in = f.width / 2 + f.boundary_width;
  const double half_overlap = scene.cameras.overlap / 2;
  const double h = scene.cameras.height;
  std::vector<CameraSpec> cams;
  if (f.division == Division::kB) {
    for (int i = 0; i < 2; ++i) {
      const double sx = i == 0 ? -1.0 : 1.0;
      CameraSpec c;
      c.id = i;
      c.position = {sx * x_in / 2, 0.0, h};
      c.min_x = sx < 0 ? -x_in : -half_overlap;
      c.max_x = sx < 0 ? half_overlap : x_in;
      c.min_y = -y_in;
      c.max_y = y_in;
      cams.push_back(c);
    }
    return cams;
  }
  // Quadrants counter-clockwise: (+,+), (-,+), (-,-), (+,-).
  const double signs[4][2] = {{1, 1}, {-1, 1}, {-1, -1}, {1, -1}};
  for (int i = 0; i < 4; ++i) {
    const double sx = signs[i][0], sy = signs[i][1];
    CameraSpec c;
    c.id = i;
    c.position = {sx * x_in / 2, sy * y_in / 2, h};
    c.min_x = sx < 0 ? -x_in : -half_overlap;
    c.max_x = sx < 0 ? half_overlap : x_in;
    c.min_y = sy < 0 ? -y_in : -half_overlap;
    c.max_y = sy < 0 ? half_overlap : y_in;
    cams.push_back(c);
  }
  return cams;
}

namespace {

bool Sees(const CameraSpec& c, double x, double y) {
  return x >= c.min_x && x <= c.max_x && y >= c.min_y && y <= c.max_y;
}

// Distance from p to the segment ab, in the plane.
double SegmentDistance(double px, double py, double ax, double ay, double bx, double by) {
  const double dx = bx - ax, dy = by - ay;
  const double len2 = dx * dx + dy * dy;
  const double t = len2 > 0 ? std::clamp(((px - ax) * dx + (py - ay) * dy) / len2, 0.0, 1.0) : 0.0;
  return std::hypot(px - (ax + t * dx), py - (ay + t * dy));
}

float Confidence(double spread, Rng& rng) {
  if (spread <= 0.0) return 1.0f;
  return static_cast<float>(std::max(0.05, 1.0 - spread * std::abs(rng.Normal())));
}

}  // namespace

Vec3 SeenBallPosition(const Vec3& camera, const Vec3& ball, double ball_radius) {
  // Below the camera and above the plane only: a ball at (or pressed below) the plane is where it is.
  if (ball.z <= ball_radius || camera.z <= ball.z) return {ball.x, ball.y, ball.z};
  const double t = (camera.z - ball_radius) / (camera.z - ball.z);
  return {camera.x + t * (ball.x - camera.x), camera.y + t * (ball.y - camera.y), ball_radius};
}

CameraFrame Detect(const CameraSpec& camera, const WorldSnapshot& world, double robot_height, double ball_radius) {
  CameraFrame frame;
  frame.camera_id = camera.id;
  frame.capture_time_ns = world.time_ns;
  frame.sent_time_ns = world.time_ns;
  const Vec3 ball = SeenBallPosition(camera.position, world.ball.position, ball_radius);
  if (Sees(camera, ball.x, ball.y)) frame.balls.push_back({ball, 1.0f});
  for (const RobotSnapshot& r : world.robots) {
    if (!r.on_field || !Sees(camera, r.x, r.y)) continue;
    frame.robots.push_back({r.team, r.id, r.x, r.y, r.yaw, robot_height, 1.0f});
  }
  return frame;
}

bool BallOccluded(const CameraSpec& camera, const Vec3& ball, const WorldSnapshot& world, double robot_radius,
                  double robot_height) {
  const Vec3& c = camera.position;
  if (ball.z >= robot_height || c.z <= robot_height) return false;
  // The part of the sight line below the robots' tops, seen from above.
  const double t = (c.z - robot_height) / (c.z - ball.z);
  const double ax = c.x + t * (ball.x - c.x), ay = c.y + t * (ball.y - c.y);
  for (const RobotSnapshot& r : world.robots) {
    if (r.on_field && SegmentDistance(r.x, r.y, ax, ay, ball.x, ball.y) < robot_radius) return true;
  }
  return false;
}

void ApplyValueModel(const CameraSpec& camera, const CameraRealism& realism, const WorldSnapshot& world,
                     const RobotParams& robot, Rng& rng, CameraFrame* frame) {
  // A fixed number of draws per object, whatever happens to it, so that one
  // object's fate never shifts another's noise.
  std::vector<DetectedBall> balls;
  for (DetectedBall b : frame->balls) {
    const bool vanished = rng.Bernoulli(realism.ball_vanish);
    const double nx = rng.Normal(0.0, realism.ball_position_stddev);
    const double ny = rng.Normal(0.0, realism.ball_position_stddev);
    const float confidence = Confidence(realism.confidence_spread, rng);
    if (vanished) continue;
    // Occlusion is of the ball itself, wherever vision will report it.
    if (realism.ball_occlusion && BallOccluded(camera, world.ball.position, world, robot.radius, robot.height))
      continue;
    b.position.x += nx;
    b.position.y += ny;
    b.confidence = confidence;
    balls.push_back(b);
  }
  frame->balls = std::move(balls);
  std::vector<DetectedRobot> robots;
  for (DetectedRobot r : frame->robots) {
    const bool vanished = rng.Bernoulli(realism.robot_vanish);
    const double nx = rng.Normal(0.0, realism.robot_position_stddev);
    const double ny = rng.Normal(0.0, realism.robot_position_stddev);
    const double nphi = rng.Normal(0.0, realism.robot_orientation_stddev);
    const float confidence = Confidence(realism.confidence_spread, rng);
    if (vanished) continue;
    r.x += nx;
    r.y += ny;
    r.orientation = std::remainder(r.orientation + nphi, 2.0 * M_PI);
    r.confidence = confidence;
    robots.push_back(r);
  }
  frame->robots = std::move(robots);
}

SslCameraSystem::SslCameraSystem(const Scene& scene)
    : scene_(scene), cameras_(CameraLayout(scene)), period_ns_(1e9 / scene.cameras.rate_hz) {
  Reset();
}

void SslCameraSystem::SetRealism(const CameraRealism& realism) {
  realism_ = realism;
  for (Stream& s : streams_) s.link.SetParams(realism.link);
}

void SslCameraSystem::Capture(const WorldSnapshot& world) {
  ++captures_;
  const int64_t processing_ns = std::llround(realism_.processing_delay * 1e9);
  for (size_t i = 0; i < cameras_.size(); ++i) {
    Stream& s = streams_[i];
    CameraFrame frame = Detect(cameras_[i], world, scene_.robot.height, scene_.ball.radius);
    frame.frame_number = captures_;
    ApplyValueModel(cameras_[i], realism_, world, scene_.robot, s.values, &frame);
    frame.sent_time_ns = frame.capture_time_ns + processing_ns;
    s.stats.Sent();
    const std::optional<int64_t> arrival = s.link.Transmit(frame.sent_time_ns);
    if (!arrival) {
      s.stats.Lost();
      continue;
    }
    // Keep the queue ordered by arrival (links of different cameras interleave).
    auto it = std::upper_bound(pending_.begin(), pending_.end(), *arrival,
                               [](int64_t t, const Pending& p) { return t < p.arrival_ns; });
    pending_.insert(it, Pending{*arrival, std::move(frame)});
  }
  // Schedule from the ideal grid, not from now, so the rate does not drift.
  next_capture_ns_ = std::llround(static_cast<double>(captures_ + 1) * period_ns_);
}

void SslCameraSystem::Release(int64_t now_ns, std::vector<CameraFrame>* out) {
  out->clear();
  while (!pending_.empty() && pending_.front().arrival_ns <= now_ns) {
    const CameraFrame& f = pending_.front().frame;
    streams_[f.camera_id].stats.Delivered((now_ns - f.capture_time_ns) * 1e-9);
    out->push_back(std::move(pending_.front().frame));
    pending_.pop_front();
  }
}

void SslCameraSystem::Reset() {
  captures_ = 0;
  next_capture_ns_ = std::llround(period_ns_);
  pending_.clear();
  streams_.clear();
  for (const CameraSpec& c : cameras_) {
    const std::string name = "camera/" + std::to_string(c.id);
    streams_.push_back(Stream{Rng(StreamSeed(scene_.seed, name + "/values")),
                              Link(realism_.link, StreamSeed(scene_.seed, name + "/link")),
                              {}});
  }
}

// Listed once (core/state_io.h).
template <class Io, class Self>
void SslCameraSystem::Fields(Io& io, Self& self) {
  constexpr size_t kMaxPending = 4096;
  io.Tag(StateTag("CAMS"));
  io(self.realism_);
  for (auto& s : self.streams_) io(s.values, s.link, s.stats);
  io(Sized(self.pending_, kMaxPending), self.captures_, self.next_capture_ns_);
  // A waiting frame's camera indexes the streams when it is released.
  for (const Pending& p : self.pending_)
    io.Check(p.frame.camera_id >= 0 && static_cast<size_t>(p.frame.camera_id) < self.streams_.size(),
             "a waiting camera frame of a camera the scene does not have");
}

void SslCameraSystem::Save(StateWriter& out) const { Fields(out, *this); }

void SslCameraSystem::Restore(StateReader& in) { Fields(in, *this); }

}  // namespace turf
