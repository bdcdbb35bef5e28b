// SSL-Vision geometry: turf's SslField (topic ssl/field, SI units) becomes an
// SSL_GeometryData in an SSL_WrapperPacket (source SSL_SOURCE_OTHER). Pure.
//
// Field sizes in int32 mm (rounded), the twelve standard lines and the centre
// circle named and typed exactly as SSL-Vision's field.cpp draws them (x along
// the length, +x right, "Left" = -x, "Top" touch line = +y), the ball models
// (straight two-phase: accelerations negative, m/s^2; chip fixed loss) and one
// calibration per camera (calibration.h).
#pragma once

#include <turf/idl/SslVision.h>

#include <cstdint>
#include <vector>

#include "codecs/proto/ssl_vision.pb.h"
#include "codecs/ssl_vision/errors.h"

namespace turf::vision {

inline constexpr size_t kMaxCameras = 64;

// Refuses a field that would encode garbage: non-finite numbers, non-positive
// sizes, a penalty area that does not fit in the field, ball accelerations
// that are positive, k_switch or chip damping outside [0, 1], a bad camera, or
// more than kMaxCameras cameras.
VisionError CheckField(const idl::SslField& field);

// Fills `out` (cleared first) from a field that passed CheckField.
void FillGeometry(const idl::SslField& field, wire::vision::SSL_GeometryData* out);

// Checks, then encodes a geometry-only SSL_WrapperPacket into `out`; on an
// error `out` is left empty.
VisionError EncodeGeometry(const idl::SslField& field, std::vector<uint8_t>* out);

}  // namespace turf::vision
