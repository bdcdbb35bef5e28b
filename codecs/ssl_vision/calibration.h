// The camera model turf publishes for SSL-Vision consumers: an ideal pinhole
// camera at CameraInfo.position looking straight down, image x along field +x
// and image y along field -y (so field +y is "up" in the image), principal
// point at the image centre, no distortion.
//
// SSL-Vision's convention (its CameraParameters::field2image): a field point
// p_f in mm maps to the camera frame as p_c = R(q) * p_f + t, then
// pixel = focal_length * (p_c.x, p_c.y) / p_c.z + principal_point. The
// quaternion is (q0, q1, q2) vector part and q3 the scalar part (as SSL-Vision,
// TIGERs' and ER-Force's readers take it); derived_camera_world_t* is the
// optical centre in the field, -R^T t. Looking straight down, R is a half turn
// about x: q = (1, 0, 0, 0) and t = (-cx, cy, cz) for a camera at (cx, cy, cz).
#pragma once

#include <turf/idl/SslVision.h>

#include "codecs/proto/ssl_vision.pb.h"
#include "codecs/ssl_vision/errors.h"

namespace turf::vision {

// Finite position with the camera above the field, positive focal length and
// image size within what a real camera has.
VisionError CheckCamera(const idl::CameraInfo& camera);

// Pixel coordinates of a field point (metres) in `camera`'s image, by the model
// above. False (and pixels untouched) if the point is not below the camera or
// projects absurdly far (beyond 1e7 pixels) from the image.
bool ProjectToPixel(const idl::CameraInfo& camera, double x, double y, double z, double* pixel_x, double* pixel_y);

// The calibration message for `camera` (call CheckCamera first).
void FillCalibration(const idl::CameraInfo& camera, wire::vision::SSL_GeometryCameraCalibration* out);

}  // namespace turf::vision
