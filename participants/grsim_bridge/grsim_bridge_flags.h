// turf-grsim-bridge's own flags (the common ones: participant_main.h), in the
// order --help lists them; the defaults are GrsimBridgeOptions'.
#pragma once

#include <vector>

#include "participants/common/participant_main.h"
#include "participants/grsim_bridge/grsim_bridge.h"

namespace turf {

// --wheel-order fills `wheel_order` (grSim wheel numbers 1..4 for turf's
// front_right, back_right, back_left, front_left); ApplyWheelOrder turns it
// into the codec's wheel_source once parsed.
void AddGrsimBridgeFlags(ParticipantMain& participant, GrsimBridgeOptions& options, std::vector<int>& wheel_order);
void ApplyWheelOrder(const std::vector<int>& wheel_order, grsim::GrsimCodecConfig& codec);

}  // namespace turf
