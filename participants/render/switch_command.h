// turf-render --switch: switches cameras of the renderers running on a domain and prefix, at run time, and exits.
// Writes each switch on <prefix>/cameras/control once a renderer reads it (waiting at most `wait`), then twice more
// 0.2 s apart (the topic is best effort; written synchronously, so all is sent before it exits). Renderers started
// later do not see it (they start as declared).
#pragma once

#include <chrono>
#include <vector>

#include "participants/render/camera_switch.h"
#include "participants/render/render_node.h"

namespace turf {

// kExitClean once written; kExitFailure when no renderer read the topic in time.
int SendCameraSwitches(const RenderOptions& options, const std::vector<CameraControlRequest>& switches,
                       std::chrono::milliseconds wait = std::chrono::seconds(10));

}  // namespace turf
