// A robot camera as a pinhole: its declaration (mount, resolution, field of view, rate, encoding), the
// intrinsics ROS's CameraInfo carries, the projection of a world point to a pixel, the camera's world pose from
// its mount body's pose, and which frames to render given the simulation times of the states that arrive.
// Pure functions and plain data: no MuJoCo, no clock, no I/O (the renderer, participants/render/, does the GL).
//
// Frames: MuJoCo's camera frame looks along -z with +y up and +x to the image's right (an MJCF <camera>'s
// xyaxes); the optical frame of ROS's CameraInfo has +z forward, +x right, +y down. Pixel (u, v) counts from the
// top-left pixel's centre (ROS's convention): the principal point of a w x h image is ((w-1)/2, (h-1)/2).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace turf {

enum class ImageEncoding {
  kRgb8,    // 3 bytes per pixel, rows top-down
  kYuv422,  // YUYV (Y0 U Y1 V per two pixels), as the Nao and the AIBO deliver; ROS calls it yuv422_yuy2
  kJpeg,    // baseline JPEG of the rgb8 image (libjpeg-turbo)
};

// "rgb8", "yuv422", "jpeg" (the scene file's names).
const char* EncodingName(ImageEncoding encoding);
std::optional<ImageEncoding> EncodingFromName(const std::string& name);
// The encoding string of sensor_msgs/Image (rgb8, yuv422_yuy2) or the format of CompressedImage (jpeg).
const char* RosEncoding(ImageEncoding encoding);

// A declared camera, resolved against the robot model (core/legged/legged_cameras.h).
struct CameraSpec {
  std::string robot;                       // scene name of the robot ("t1")
  std::string name;                        // the camera's name within the robot ("camera", "top")
  std::string body;                        // mount body, the robot file's name ("head")
  std::array<double, 3> pos{0, 0, 0};      // camera origin in the body frame, m
  std::array<double, 4> quat{1, 0, 0, 0};  // body <- camera (MuJoCo camera frame), w x y z
  int width = 320;
  int height = 240;
  double hfov = 1.0;  // horizontal field of view, rad
  double rate_hz = 30.0;
  ImageEncoding encoding = ImageEncoding::kRgb8;
  int jpeg_quality = 80;      // 1..100
  double noise_stddev = 0.0;  // Gaussian pixel noise per channel, in 8-bit steps (0: none), seeded per frame
  bool enabled = true;
};

// Limits a declaration is checked against.
inline constexpr int kMaxImageSide = 4096;
inline constexpr double kMaxCameraRateHz = 1000.0;
inline constexpr double kMinCameraRateHz = 1e-3;  // a frame every 1000 s (1e-10 Hz overflowed the period: every state)

// "t1/camera": the camera's unique name in a scene.
std::string CameraId(const CameraSpec& camera);

struct Intrinsics {
  int width = 0;
  int height = 0;
  double fx = 0, fy = 0;  // focal lengths in pixels (square pixels: fx == fy)
  double cx = 0, cy = 0;  // principal point, pixels from the top-left pixel's centre
};

Intrinsics IntrinsicsOf(int width, int height, double hfov);
// The vertical field of view of an image of that size and horizontal field of view (square pixels), rad.
double VerticalFov(int width, int height, double hfov);
// The horizontal field of view from a vertical one (an MJCF camera's fovy).
double HorizontalFov(int width, int height, double vfov);

// A pinhole's projection of a point in the optical frame (z forward); none behind the camera (z <= 0).
std::optional<std::array<double, 2>> ProjectOptical(const Intrinsics& k, const std::array<double, 3>& p);

struct Pose {
  std::array<double, 3> position{0, 0, 0};
  std::array<double, 4> orientation{1, 0, 0, 0};  // world <- frame, w x y z
};

// The camera's world pose (world <- MuJoCo camera frame) from its mount body's.
Pose CameraWorldPose(const Pose& body, const CameraSpec& camera);
// A world point in the camera's optical frame.
std::array<double, 3> WorldToOptical(const Pose& camera, const std::array<double, 3>& world);
// The camera's viewing direction (-z) and image up (+y) in the world, for a GL camera.
std::array<double, 3> CameraForward(const Pose& camera);
std::array<double, 3> CameraUp(const Pose& camera);

// Seeded camera noise: adds N(0, stddev) to every byte of an 8-bit image (clamped), drawn from the stream
// "camera/<robot>/<camera>" of the scene seed and the frame's simulation time, so a frame's noise depends on
// nothing else (not on which renderer drew it or how many frames were dropped).
void AddPixelNoise(std::vector<uint8_t>* pixels, double stddev, uint64_t scene_seed, const CameraSpec& camera,
                   int64_t sim_time_ns);

// Which states to render, by simulation time: one frame per period, due at multiples of the period. A state at
// or past the next due time is rendered (the frame carries that state's time) and the due time moves on by one
// period; due times that passed with no state rendered (the renderer was busy, or states came slower than the
// camera's rate) are counted as dropped. Time going back (a reset) starts over.
class FrameSchedule {
 public:
  explicit FrameSchedule(double rate_hz);

  // True if the state at `sim_time_ns` is to be rendered.
  bool Offer(int64_t sim_time_ns);

  int64_t period_ns() const { return period_ns_; }
  uint64_t rendered() const { return rendered_; }
  uint64_t dropped() const { return dropped_; }

 private:
  int64_t period_ns_;
  std::optional<int64_t> next_due_ns_;
  int64_t last_ns_ = 0;
  uint64_t rendered_ = 0;
  uint64_t dropped_ = 0;
};

}  // namespace turf
