// turf-vision-bridge's own flags (the common ones: participant_main.h), in the
// order --help lists them; the defaults are VisionBridgeOptions'.
#pragma once

#include <string>

#include "participants/common/participant_main.h"
#include "participants/vision_bridge/vision_bridge.h"

namespace turf {

// --clock fills `clock` ("run", "unix" or "sim", checked by the parser), which
// vision::ParseClockMode turns into options.clock once parsed.
void AddVisionBridgeFlags(ParticipantMain& participant, VisionBridgeOptions& options, std::string& clock);

}  // namespace turf
