// Snapshot fields of core's plain structs (state_io.h's format, field by
// field). Each Restore* fails the reader on a value no Save* writes.
#pragma once

#include "core/ball_handling.h"
#include "core/sensor_realism.h"
#include "core/ssl_cameras.h"
#include "core/state_io.h"
#include "core/stream_stats.h"
#include "core/types.h"

namespace turf {

void SaveCommand(const RobotCommand& c, StateWriter& out);
RobotCommand RestoreCommand(StateReader& in);

void SaveArmedKick(const ArmedKick& k, StateWriter& out);
ArmedKick RestoreArmedKick(StateReader& in);

void SaveCameraFrame(const CameraFrame& f, StateWriter& out);
CameraFrame RestoreCameraFrame(StateReader& in);

void SaveRealism(const SensorRealism& r, StateWriter& out);
SensorRealism RestoreRealism(StateReader& in);

}  // namespace turf
