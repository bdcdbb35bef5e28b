#include "core/ssl_cameras.h"

#include <cmath>

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
}  // namespace

CameraFrame Detect(const CameraSpec& camera, const WorldSnapshot& world, double robot_height) {
  CameraFrame frame;
  frame.camera_id = camera.id;
  frame.capture_time_ns = world.time_ns;
  frame.sent_time_ns = world.time_ns;
  if (Sees(camera, world.ball.position.x, world.ball.position.y)) frame.balls.push_back({world.ball.position, 1.0f});
  for (const RobotSnapshot& r : world.robots) {
    if (!r.on_field || !Sees(camera, r.x, r.y)) continue;
    frame.robots.push_back({r.team, r.id, r.x, r.y, r.yaw, robot_height, 1.0f});
  }
  return frame;
}

SslCameraSystem::SslCameraSystem(const Scene& scene)
    : cameras_(CameraLayout(scene)), robot_height_(scene.robot.height), period_ns_(1e9 / scene.cameras.rate_hz) {
  Reset();
}

void SslCameraSystem::Capture(const WorldSnapshot& world, std::vector<CameraFrame>* out) {
  out->clear();
  ++captures_;
  for (const CameraSpec& c : cameras_) {
    out->push_back(Detect(c, world, robot_height_));
    out->back().frame_number = captures_;
  }
  // Schedule from the ideal grid, not from now, so the rate does not drift.
  next_capture_ns_ = std::llround(static_cast<double>(captures_ + 1) * period_ns_);
}

void SslCameraSystem::Reset() {
  captures_ = 0;
  next_capture_ns_ = std::llround(period_ns_);
}

}  // namespace turf
