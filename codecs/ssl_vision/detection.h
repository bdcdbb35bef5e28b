// SSL-Vision detections: one turf CameraFrame (topic ssl/camera, SI units)
// becomes one SSL_DetectionFrame in an SSL_WrapperPacket (millimetres,
// radians, robots split by team, source SSL_SOURCE_OTHER). Pure functions.
//
// Per ball: confidence, x, y, z (mm; z is the ball centre's height), pixel_x/y.
// Per robot: confidence, robot_id, x, y, orientation, height (mm), pixel_x/y.
// Pixels come from calibration.h's model of `camera`; with no camera they are 0.
// frame_number is the camera's frame number modulo 2^32.
#pragma once

#include <turf/idl/SslVision.h>

#include <cstdint>
#include <vector>

#include "codecs/proto/ssl_vision.pb.h"
#include "codecs/ssl_vision/errors.h"

namespace turf::vision {

struct FrameTimes {
  double t_capture;  // seconds, already in the chosen clock (timestamps.h)
  double t_sent;
};

// Most detections of one kind a frame may carry (a camera sees each robot once).
inline constexpr size_t kMaxDetections = 64;
inline constexpr uint32_t kMaxRobotId = 15;

// Refuses what must not reach the wire: non-finite numbers, positions beyond
// 1 km, confidences outside [0, 1], robot ids > 15, unknown teams, and more
// than kMaxDetections balls or robots. Untrusted input: call before encoding.
VisionError CheckCameraFrame(const idl::CameraFrame& frame);

// Fills `out` (cleared first) from a frame that passed CheckCameraFrame.
// `camera` (may be null) gives pixel coordinates by a pinhole projection of a
// camera looking straight down.
void FillDetectionFrame(const idl::CameraFrame& frame, const FrameTimes& times, const idl::CameraInfo* camera,
                        wire::vision::SSL_DetectionFrame* out);

// The SSL_WrapperPacket bytes with the detection and source = SSL_SOURCE_OTHER.
std::vector<uint8_t> EncodeDetection(const idl::CameraFrame& frame, const FrameTimes& times,
                                     const idl::CameraInfo* camera);

// The camera of `field` with this id, or null.
const idl::CameraInfo* FindCamera(const idl::SslField& field, uint32_t camera_id);

}  // namespace turf::vision
