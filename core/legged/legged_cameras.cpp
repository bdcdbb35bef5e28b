#include "core/legged/legged_cameras.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "core/legged/legged_mjcf.h"

namespace turf {

namespace {

// The robot's own name of a composed element ("t1/camera" -> "camera"), or "" if it is not the robot's.
std::string OwnName(const std::string& composed, const std::string& robot) {
  const std::string prefix = LeggedElementName(robot, "");
  return composed.rfind(prefix, 0) == 0 ? composed.substr(prefix.size()) : std::string();
}

// The rotation body <- camera whose x and y axes are `xy` (MJCF's xyaxes: z = x cross y).
std::array<double, 4> QuatFromXyAxes(const std::array<double, 6>& xy, bool* ok) {
  mjtNum x[3] = {xy[0], xy[1], xy[2]};
  mjtNum y[3] = {xy[3], xy[4], xy[5]};
  // Components up to 1e6 (1e300 squared to infinity: the axis normalized to zero and the camera turned anyhow).
  *ok = std::all_of(xy.begin(), xy.end(), [](double v) { return std::isfinite(v) && std::abs(v) <= 1e6; });
  *ok = mju_normalize3(x) > mjMINVAL && *ok;
  const mjtNum d = mju_dot3(x, y);
  for (int i = 0; i < 3; ++i) y[i] -= d * x[i];
  *ok = *ok && mju_normalize3(y) > mjMINVAL;
  mjtNum z[3];
  mju_cross(z, x, y);
  const mjtNum mat[9] = {x[0], y[0], z[0], x[1], y[1], z[1], x[2], y[2], z[2]};
  mjtNum q[4];
  mju_mat2Quat(q, mat);
  return {q[0], q[1], q[2], q[3]};
}

// A CameraSpec from the MJCF camera `cam` of robot `robot`.
CameraSpec FromModel(const mjModel* m, int cam, const std::string& robot) {
  CameraSpec c;
  c.robot = robot;
  c.name = OwnName(mj_id2name(m, mjOBJ_CAMERA, cam), robot);
  c.body = OwnName(mj_id2name(m, mjOBJ_BODY, m->cam_bodyid[cam]), robot);
  for (int i = 0; i < 3; ++i) c.pos[i] = m->cam_pos[3 * cam + i];
  for (int i = 0; i < 4; ++i) c.quat[i] = m->cam_quat[4 * cam + i];
  c.hfov = HorizontalFov(c.width, c.height, m->cam_fovy[cam] * M_PI / 180.0);
  return c;
}

void Apply(const CameraDecl& d, const mjModel* m, bool from_model, double model_vfov, CameraSpec* c,
           std::vector<std::string>* errors, const std::string& where) {
  if (d.body) {
    if (mj_name2id(m, mjOBJ_BODY, LeggedElementName(c->robot, *d.body).c_str()) < 0)
      errors->push_back(fmt::format("{}: body '{}' is not a body of the robot", where, *d.body));
    c->body = *d.body;
  }
  if (d.pos) c->pos = *d.pos;
  if (d.xyaxes) {
    bool ok = false;
    c->quat = QuatFromXyAxes(*d.xyaxes, &ok);
    if (!ok)
      errors->push_back(
          fmt::format("{}: xyaxes must be two independent non-zero vectors, components within 1e6", where));
  }
  if (d.width) c->width = *d.width;
  if (d.height) c->height = *d.height;
  if (d.hfov)
    c->hfov = *d.hfov;
  else if (from_model)  // keep the MJCF camera's vertical field of view at the declared size
    c->hfov = HorizontalFov(c->width, c->height, model_vfov);
  if (d.rate_hz) c->rate_hz = *d.rate_hz;
  if (d.encoding) {
    const auto e = EncodingFromName(*d.encoding);
    if (!e)
      errors->push_back(fmt::format("{}: encoding '{}' is not one of rgb8, yuv422, jpeg", where, *d.encoding));
    else
      c->encoding = *e;
  }
  if (d.jpeg_quality) c->jpeg_quality = *d.jpeg_quality;
  if (d.noise_stddev) c->noise_stddev = *d.noise_stddev;
  if (d.enabled) c->enabled = *d.enabled;
}

}  // namespace

std::vector<std::string> ValidateCamera(const CameraSpec& c) {
  std::vector<std::string> e;
  if (c.width < 2 || c.width > kMaxImageSide || c.width % 2 != 0)
    e.push_back(fmt::format("width {} must be even, 2..{}", c.width, kMaxImageSide));
  if (c.height < 1 || c.height > kMaxImageSide)
    e.push_back(fmt::format("height {} must be 1..{}", c.height, kMaxImageSide));
  if (!(c.hfov > 0 && c.hfov < M_PI * 170.0 / 180.0))
    e.push_back(fmt::format("hfov_deg {} must be in (0, 170)", c.hfov * 180.0 / M_PI));
  if (!(c.rate_hz >= kMinCameraRateHz && c.rate_hz <= kMaxCameraRateHz))
    e.push_back(fmt::format("rate_hz {} must be in [{}, {}]", c.rate_hz, kMinCameraRateHz, kMaxCameraRateHz));
  if (c.jpeg_quality < 1 || c.jpeg_quality > 100)
    e.push_back(fmt::format("jpeg_quality {} must be 1..100", c.jpeg_quality));
  if (!(c.noise_stddev >= 0 && c.noise_stddev <= 255))
    e.push_back(fmt::format("noise_stddev {} must be in [0, 255]", c.noise_stddev));
  for (double v : c.pos)
    if (!std::isfinite(v) || std::abs(v) > 10) e.push_back("pos must be finite and within 10 m of the body");
  for (const std::string& token : {c.robot, c.name}) {
    const bool ok = !token.empty() && token.find_first_not_of(
                                          "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                          "0123456789_") == std::string::npos;
    if (!ok)
      e.push_back(
          fmt::format("'{}' cannot name a ROS topic: letters, digits and _ only (the robot and the camera "
                      "name its topics)",
                      token));
  }
  return e;
}

LeggedCameras ResolveLeggedCameras(const LeggedScene& scene, const mjModel* m) {
  LeggedCameras out;
  for (size_t r = 0; r < scene.robots.size(); ++r) {
    const LeggedRobot& robot = scene.robots[r];
    const size_t first = out.cameras.size();
    for (int cam = 0; cam < m->ncam; ++cam) {
      const char* name = mj_id2name(m, mjOBJ_CAMERA, cam);
      if (name != nullptr && !OwnName(name, robot.name).empty()) out.cameras.push_back(FromModel(m, cam, robot.name));
    }
    for (const CameraDecl& d : robot.cameras) {
      const std::string where = fmt::format("robots[{}] ({}): camera '{}'", r, robot.name, d.name);
      const int cam = mj_name2id(m, mjOBJ_CAMERA, LeggedElementName(robot.name, d.name).c_str());
      CameraSpec* c = nullptr;
      for (size_t i = first; i < out.cameras.size(); ++i)
        if (out.cameras[i].name == d.name) c = &out.cameras[i];
      if (c == nullptr) {
        if (!d.body) {
          out.errors.push_back(where + ": the robot file has no camera of that name, so `body` is required");
          continue;
        }
        out.cameras.push_back(CameraSpec{});
        c = &out.cameras.back();
        c->robot = robot.name;
        c->name = d.name;
      }
      const double vfov = cam >= 0 ? m->cam_fovy[cam] * M_PI / 180.0 : 0.0;
      Apply(d, m, cam >= 0, vfov, c, &out.errors, where);
    }
    for (size_t i = first; i < out.cameras.size(); ++i)
      for (const std::string& e : ValidateCamera(out.cameras[i]))
        out.errors.push_back(fmt::format("robots[{}] ({}): camera '{}': {}", r, robot.name, out.cameras[i].name, e));
  }
  return out;
}

}  // namespace turf
