// Conversions between the core's values and the DDS types. Samples from other
// participants are untrusted: From* functions check what the core's own
// validation cannot see (enum values, ids that do not fit) and name the error.
#pragma once

#include <turf/idl/Clock.h>
#include <turf/idl/SimControl.h>
#include <turf/idl/SslRobot.h>
#include <turf/idl/SslVision.h>
#include <turf/idl/WorldState.h>

#include "core/scene.h"
#include "core/ssl_cameras.h"
#include "core/types.h"
#include "core/world.h"

namespace turf {

void ToIdl(const WorldSnapshot& snapshot, idl::WorldState* out);
void ToIdl(const CameraFrame& frame, idl::CameraFrame* out);
idl::SslField FieldToIdl(const Scene& scene, const std::vector<CameraSpec>& cameras);
idl::SslRobotFeedback FeedbackToIdl(const RobotSnapshot& robot, int64_t time_ns);
idl::Team ToIdl(Team team);

InputError FromIdl(const idl::SslRobotCommand& in, RobotCommand* out);
InputError FromIdl(const idl::BallTeleport& in, BallTeleport* out);
InputError FromIdl(const idl::RobotTeleport& in, RobotTeleport* out);
bool FromIdl(idl::Team in, Team* out);

}  // namespace turf
