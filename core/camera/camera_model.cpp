#include "core/camera/camera_model.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "core/rng.h"

namespace turf {

namespace {

using Vec3 = std::array<double, 3>;
using Quat = std::array<double, 4>;

Quat Multiply(const Quat& a, const Quat& b) {
  return {a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3], a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
          a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1], a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0]};
}

// v rotated by the unit quaternion q.
Vec3 Rotate(const Quat& q, const Vec3& v) {
  const Quat p = Multiply(Multiply(q, {0, v[0], v[1], v[2]}), {q[0], -q[1], -q[2], -q[3]});
  return {p[1], p[2], p[3]};
}

Quat Normalized(const Quat& q) {
  const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  if (!(n > 0)) return {1, 0, 0, 0};
  return {q[0] / n, q[1] / n, q[2] / n, q[3] / n};
}

// By ImageEncoding's value: each encoding's name in turf's files and flags, and in a ROS sensor_msgs/Image.
constexpr size_t kEncodings = 3;
constexpr const char* kEncodingNames[kEncodings] = {"rgb8", "yuv422", "jpeg"};
constexpr const char* kRosEncodings[kEncodings] = {"rgb8", "yuv422_yuy2", "jpeg"};

const char* NameIn(const char* const (&names)[kEncodings], ImageEncoding encoding) {
  const auto i = static_cast<size_t>(encoding);
  return i < kEncodings ? names[i] : "?";
}

int64_t CeilToMultiple(int64_t t, int64_t period) {
  const int64_t q = t / period;
  const int64_t m = q * period;
  return m >= t ? m : m + period;
}

}  // namespace

const char* EncodingName(ImageEncoding encoding) { return NameIn(kEncodingNames, encoding); }

std::optional<ImageEncoding> EncodingFromName(const std::string& name) {
  for (size_t i = 0; i < kEncodings; ++i)
    if (name == kEncodingNames[i]) return static_cast<ImageEncoding>(i);
  return std::nullopt;
}

const char* RosEncoding(ImageEncoding encoding) { return NameIn(kRosEncodings, encoding); }

std::string CameraId(const CameraSpec& camera) { return camera.robot + "/" + camera.name; }

Intrinsics IntrinsicsOf(int width, int height, double hfov) {
  Intrinsics k;
  k.width = width;
  k.height = height;
  k.fx = 0.5 * width / std::tan(0.5 * hfov);
  k.fy = k.fx;
  k.cx = 0.5 * (width - 1);
  k.cy = 0.5 * (height - 1);
  return k;
}

double VerticalFov(int width, int height, double hfov) {
  return 2.0 * std::atan(std::tan(0.5 * hfov) * height / width);
}

double HorizontalFov(int width, int height, double vfov) {
  return 2.0 * std::atan(std::tan(0.5 * vfov) * width / height);
}

std::optional<std::array<double, 2>> ProjectOptical(const Intrinsics& k, const std::array<double, 3>& p) {
  if (!(p[2] > 0)) return std::nullopt;
  return std::array<double, 2>{k.cx + k.fx * p[0] / p[2], k.cy + k.fy * p[1] / p[2]};
}

Pose CameraWorldPose(const Pose& body, const CameraSpec& camera) {
  const Quat q = Normalized(body.orientation);
  const Vec3 offset = Rotate(q, camera.pos);
  Pose out;
  for (int i = 0; i < 3; ++i) out.position[i] = body.position[i] + offset[i];
  out.orientation = Normalized(Multiply(q, Normalized(camera.quat)));
  return out;
}

std::array<double, 3> WorldToOptical(const Pose& camera, const std::array<double, 3>& world) {
  const Quat& q = camera.orientation;
  const Vec3 d{world[0] - camera.position[0], world[1] - camera.position[1], world[2] - camera.position[2]};
  const Vec3 c = Rotate({q[0], -q[1], -q[2], -q[3]}, d);  // in MuJoCo's camera frame
  return {c[0], -c[1], -c[2]};
}

std::array<double, 3> CameraForward(const Pose& camera) { return Rotate(camera.orientation, {0, 0, -1}); }
std::array<double, 3> CameraUp(const Pose& camera) { return Rotate(camera.orientation, {0, 1, 0}); }

void AddPixelNoise(std::vector<uint8_t>* pixels, double stddev, uint64_t scene_seed, const CameraSpec& camera,
                   int64_t sim_time_ns) {
  if (!(stddev > 0)) return;
  Rng rng(StreamSeed(scene_seed, "camera/" + CameraId(camera) + "/" + std::to_string(sim_time_ns)));
  for (uint8_t& p : *pixels) p = static_cast<uint8_t>(std::clamp(std::lround(p + rng.Normal(0.0, stddev)), 0L, 255L));
}

FrameSchedule::FrameSchedule(double rate_hz)
    : period_ns_(std::llround(std::clamp(1e9 / rate_hz, 1.0, 1e9 / kMinCameraRateHz))) {}

bool FrameSchedule::Offer(int64_t sim_time_ns) {
  if (!next_due_ns_ || sim_time_ns < last_ns_) next_due_ns_ = CeilToMultiple(sim_time_ns, period_ns_);
  last_ns_ = sim_time_ns;
  if (sim_time_ns < *next_due_ns_) return false;
  const int64_t missed = (sim_time_ns - *next_due_ns_) / period_ns_;
  dropped_ += static_cast<uint64_t>(missed);
  *next_due_ns_ += (missed + 1) * period_ns_;
  ++rendered_;
  return true;
}

}  // namespace turf
