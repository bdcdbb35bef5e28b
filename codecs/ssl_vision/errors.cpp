#include "codecs/ssl_vision/errors.h"

namespace turf::vision {

const char* VisionErrorName(VisionError error) {
  switch (error) {
    case VisionError::kOk:
      return "ok";
    case VisionError::kNotFinite:
      return "not_finite";
    case VisionError::kOutOfRange:
      return "out_of_range";
    case VisionError::kNonPositiveSize:
      return "non_positive_size";
    case VisionError::kBadRobotId:
      return "bad_robot_id";
    case VisionError::kUnknownTeam:
      return "unknown_team";
    case VisionError::kTooMany:
      return "too_many";
    case VisionError::kTimeNotPositive:
      return "time_not_positive";
    case VisionError::kTimeOrder:
      return "time_order";
    case VisionError::kNoEpoch:
      return "no_epoch";
    case VisionError::kBadEpoch:
      return "bad_epoch";
  }
  return "unknown_error";
}

}  // namespace turf::vision
