#include "codecs/ssl_vision/calibration.h"

#include <cmath>

namespace turf::vision {

namespace {

constexpr double kMm = 1000.0;
constexpr double kMaxCameraCoordinate = 1000.0;  // m
constexpr uint32_t kMaxImageSide = 100000;       // pixels
constexpr double kMaxPixel = 1e7;                // far outside any image, still a sane float

bool Finite(const idl::Vec3& v) { return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z()); }

}  // namespace

VisionError CheckCamera(const idl::CameraInfo& camera) {
  const idl::Vec3& p = camera.position();
  if (!Finite(p) || !std::isfinite(camera.focal_length())) return VisionError::kNotFinite;
  if (camera.focal_length() <= 0.0 || p.z() <= 0.0 || camera.image_width() == 0 || camera.image_height() == 0)
    return VisionError::kNonPositiveSize;
  if (std::abs(p.x()) > kMaxCameraCoordinate || std::abs(p.y()) > kMaxCameraCoordinate ||
      p.z() > kMaxCameraCoordinate || camera.focal_length() > 1e6 || camera.image_width() > kMaxImageSide ||
      camera.image_height() > kMaxImageSide)
    return VisionError::kOutOfRange;
  return VisionError::kOk;
}

bool ProjectToPixel(const idl::CameraInfo& camera, double x, double y, double z, double* pixel_x, double* pixel_y) {
  const idl::Vec3& c = camera.position();
  const double depth = c.z() - z;  // p_c.z: distance below the optical centre
  if (!(depth > 0.0) || !std::isfinite(depth)) return false;
  const double px = 0.5 * camera.image_width() + camera.focal_length() * (x - c.x()) / depth;
  const double py = 0.5 * camera.image_height() - camera.focal_length() * (y - c.y()) / depth;
  if (!(std::abs(px) <= kMaxPixel && std::abs(py) <= kMaxPixel)) return false;
  *pixel_x = px;
  *pixel_y = py;
  return true;
}

void FillCalibration(const idl::CameraInfo& camera, wire::vision::SSL_GeometryCameraCalibration* out) {
  const idl::Vec3& c = camera.position();
  out->set_camera_id(camera.id());
  out->set_focal_length(static_cast<float>(camera.focal_length()));
  out->set_principal_point_x(static_cast<float>(0.5 * camera.image_width()));
  out->set_principal_point_y(static_cast<float>(0.5 * camera.image_height()));
  out->set_distortion(0.0f);
  // A half turn about field x: (q0, q1, q2) = axis * sin(pi/2), q3 = cos(pi/2).
  out->set_q0(1.0f);
  out->set_q1(0.0f);
  out->set_q2(0.0f);
  out->set_q3(0.0f);
  // t = -R c with R = diag(1, -1, -1); "+ 0.0" turns -0 into 0.
  out->set_tx(static_cast<float>(-c.x() * kMm + 0.0));
  out->set_ty(static_cast<float>(c.y() * kMm));
  out->set_tz(static_cast<float>(c.z() * kMm));
  out->set_derived_camera_world_tx(static_cast<float>(c.x() * kMm));
  out->set_derived_camera_world_ty(static_cast<float>(c.y() * kMm));
  out->set_derived_camera_world_tz(static_cast<float>(c.z() * kMm));
  out->set_pixel_image_width(camera.image_width());
  out->set_pixel_image_height(camera.image_height());
}

}  // namespace turf::vision
