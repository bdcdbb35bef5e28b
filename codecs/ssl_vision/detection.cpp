#include "codecs/ssl_vision/detection.h"

#include <cmath>
#include <initializer_list>

#include "codecs/ssl_vision/calibration.h"

namespace turf::vision {

namespace {

constexpr double kMm = 1000.0;
constexpr double kMaxCoordinate = 1000.0;  // m; the largest SSL field is 13.2 m long
constexpr double kTwoPi = 6.283185307179586;

VisionError CheckNumber(double v, double limit) {
  if (!std::isfinite(v)) return VisionError::kNotFinite;
  return std::abs(v) <= limit ? VisionError::kOk : VisionError::kOutOfRange;
}

VisionError CheckConfidence(float c) {
  if (!std::isfinite(c)) return VisionError::kNotFinite;
  return c >= 0.0f && c <= 1.0f ? VisionError::kOk : VisionError::kOutOfRange;
}

// The first error of a list of checks.
VisionError First(std::initializer_list<VisionError> errors) {
  for (VisionError e : errors)
    if (e != VisionError::kOk) return e;
  return VisionError::kOk;
}

float Mm(double metres) { return static_cast<float>(metres * kMm); }

// SSL-Vision reports orientations in [-pi, pi].
float Angle(double rad) { return static_cast<float>(std::remainder(rad, kTwoPi)); }

}  // namespace

VisionError CheckCameraFrame(const idl::CameraFrame& frame) {
  if (frame.balls().size() > kMaxDetections || frame.robots().size() > kMaxDetections) return VisionError::kTooMany;
  for (const idl::DetectedBall& b : frame.balls()) {
    const idl::Vec3& p = b.position();
    const VisionError e = First({CheckNumber(p.x(), kMaxCoordinate), CheckNumber(p.y(), kMaxCoordinate),
                                 CheckNumber(p.z(), kMaxCoordinate), CheckConfidence(b.confidence())});
    if (e != VisionError::kOk) return e;
  }
  for (const idl::DetectedRobot& r : frame.robots()) {
    const VisionError e =
        First({CheckNumber(r.position().x(), kMaxCoordinate), CheckNumber(r.position().y(), kMaxCoordinate),
               CheckNumber(r.orientation(), kMaxCoordinate), CheckNumber(r.height(), kMaxCoordinate),
               CheckConfidence(r.confidence())});
    if (e != VisionError::kOk) return e;
    if (r.team() != idl::TEAM_BLUE && r.team() != idl::TEAM_YELLOW) return VisionError::kUnknownTeam;
    if (r.id() > kMaxRobotId) return VisionError::kBadRobotId;
  }
  return VisionError::kOk;
}

void FillDetectionFrame(const idl::CameraFrame& frame, const FrameTimes& times, const idl::CameraInfo* camera,
                        wire::vision::SSL_DetectionFrame* out) {
  out->Clear();
  out->set_frame_number(static_cast<uint32_t>(frame.frame_number()));
  out->set_t_capture(times.t_capture);
  out->set_t_sent(times.t_sent);
  out->set_camera_id(frame.camera_id());
  auto pixels = [camera](double x, double y, double z, auto* o) {
    double px = 0.0, py = 0.0;
    if (camera != nullptr) ProjectToPixel(*camera, x, y, z, &px, &py);
    o->set_pixel_x(static_cast<float>(px));
    o->set_pixel_y(static_cast<float>(py));
  };
  for (const idl::DetectedBall& b : frame.balls()) {
    wire::vision::SSL_DetectionBall* o = out->add_balls();
    const idl::Vec3& p = b.position();
    o->set_confidence(b.confidence());
    o->set_x(Mm(p.x()));
    o->set_y(Mm(p.y()));
    // No z, as SSL-Vision: x and y are the blob's projection onto the carpet plane (core/ssl_cameras.h).
    pixels(p.x(), p.y(), p.z(), o);
  }
  for (const idl::DetectedRobot& r : frame.robots()) {
    wire::vision::SSL_DetectionRobot* o =
        r.team() == idl::TEAM_YELLOW ? out->add_robots_yellow() : out->add_robots_blue();
    o->set_confidence(r.confidence());
    o->set_robot_id(r.id());
    o->set_x(Mm(r.position().x()));
    o->set_y(Mm(r.position().y()));
    o->set_orientation(Angle(r.orientation()));
    // SSL-Vision sees the pattern on the robot's top.
    pixels(r.position().x(), r.position().y(), r.height(), o);
    o->set_height(Mm(r.height()));
  }
}

std::vector<uint8_t> EncodeDetection(const idl::CameraFrame& frame, const FrameTimes& times,
                                     const idl::CameraInfo* camera) {
  wire::vision::SSL_WrapperPacket packet;
  FillDetectionFrame(frame, times, camera, packet.mutable_detection());
  packet.set_source(wire::vision::SSL_SOURCE_OTHER);
  std::vector<uint8_t> bytes(packet.ByteSizeLong());
  packet.SerializeToArray(bytes.data(), static_cast<int>(bytes.size()));
  return bytes;
}

const idl::CameraInfo* FindCamera(const idl::SslField& field, uint32_t camera_id) {
  for (const idl::CameraInfo& c : field.cameras())
    if (c.id() == camera_id) return &c;
  return nullptr;
}

}  // namespace turf::vision
