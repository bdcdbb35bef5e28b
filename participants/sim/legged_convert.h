// Conversions between the legged kernel's values and the DDS types (topics
// in sim_node.h). Samples from other participants are untrusted: FromIdl
// names what the kernel's own validation cannot see (an unknown mode).
#pragma once

#include <turf/idl/Joints.h>

#include <array>

#include "core/legged/legged_world.h"
#include "idl/values.h"

namespace turf {

using idl::A3;
using idl::Q4;
using idl::V3;
idl::GeomShape ToIdl(LeggedGeom::Shape shape);

// One robot's stream samples (reusing the output's storage).
void FillJoints(const LeggedRobotState& r, int64_t time_ns, uint64_t frame, idl::JointState* joints);
void FillImu(const LeggedRobotState& r, int64_t time_ns, idl::ImuState* imu);
void FillForce(const LeggedRobotState& r, int64_t time_ns, idl::ForceState* force);
void FillLinks(const LeggedRobotState& r, int64_t time_ns, uint64_t frame, idl::LinkState* links);
// The whole frame: every robot's four samples and the ball.
void FillState(const LeggedWorldState& state, idl::LeggedState* out);

// False for a joint mode this build does not know.
bool FromIdl(const idl::JointTarget& in, JointCommand* out);

}  // namespace turf
