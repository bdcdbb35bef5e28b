// turf-hlvs-bridge: the RoboCup Humanoid League virtual season's robot API (shared/protocols/hlvs.md) in front of
// turf-sim running a legged scene (configs/scenes/hlvs.yaml), so HLVS team programs drive turf's robots unchanged.
//
// Robots and ports: a scene robot named red_<n> or blue_<n> (n = 1..4) is served on its team's port n (red
// 10001..10004, blue 10021..10024, as game.json's defaults); other robots are not served. One client per robot at a
// time; its address must be in its team's allowlist (default: 127.0.0.1 and the facts' 192.168.123.21-24 /
// .41-44), else it gets `Refused\0` and is closed. An accepted client gets `Welcome\0`, then framed
// ActuatorRequests in and one SensorMeasurements per 8 ms step out (codecs/hlvs/session.h: motors, sensor time
// steps, warnings; quotas for team_players robots per team). A second client while the first is connected is refused
// the same way (the reference leaves it waiting in the listen backlog); one whose predecessor has closed is welcome.
// Robot tables: codecs/hlvs/robots.cpp.
//
// Time: the bridge is the clock. It holds turf-sim in lockstep and steps it 8 ms of simulated time per step (the
// scene's physics step must divide 8 ms), a step every 8 ms / realtime_factor of wall time (<= 0: as fast as
// possible), never waiting for clients (as the reference). Per step: the requests that arrived are applied, the
// measurement of this step is sent, the joint commands go out with the next OP_STEP.
//
// Untrusted input: a frame above 64 KiB, bytes that are no ActuatorRequests, a NaN, an infinity other than a
// position, a value out of range, too many entries: that request is refused whole, counted by kind, and its client
// dropped; the robot keeps its last accepted commands. A client that stops reading (1 MiB unsent) is dropped too.
// A step turf-sim refuses for its joint commands (a scene whose motors.max_speed is below the HLVS table's) is
// counted (step_refused) and stepped again without them. Counters: README.md beside this file.
//
// Writes: control (SimControl: OP_SET_TIME_MODE, OP_STEP with joint commands). Reads: legged/scene, robots/state,
// clock, control_reply (participants/common/legged_lockstep.h).
//
// Cameras: accepted in requests (time steps with the quota, exposure); images come from a hlvs::CameraSource
// (SetCameraSource; main.cpp gives it turf-render's topics, dds_camera_source.h). With none, or with no new frame
// when a camera is due, the camera is left out of that SensorMeasurements (logged once per robot).
#pragma once

#include <chrono>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "participants/common/participant_options.h"
#include "participants/lockstep_front_end/front_end_handle.h"

namespace turf::hlvs {
class CameraSource;
}  // namespace turf::hlvs

namespace turf {

struct HlvsBridgeOptions : ParticipantOptions {
  HlvsBridgeOptions() { name = "turf-hlvs-bridge"; }
  std::string listen = "0.0.0.0";                                  // as the reference
  std::vector<uint16_t> red_ports = {10001, 10002, 10003, 10004};  // player n: ports[n - 1]; 0: any free port
  std::vector<uint16_t> blue_ports = {10021, 10022, 10023, 10024};
  std::vector<std::string> red_allow = {"127.0.0.1", "192.168.123.21", "192.168.123.22", "192.168.123.23",
                                        "192.168.123.24"};
  std::vector<std::string> blue_allow = {"127.0.0.1", "192.168.123.41", "192.168.123.42", "192.168.123.43",
                                         "192.168.123.44"};
  int team_players = 4;          // robots per team, for the quotas
  double realtime_factor = 1.0;  // game.json's maximum_real_time_factor; <= 0: as fast as possible
  std::chrono::milliseconds attach_timeout{30000};
  std::chrono::milliseconds step_timeout{5000};
  size_t max_unsent = 1 << 20;
  double duration = 0.0;  // simulated seconds, then Run returns (0: until stopped)
};

struct HlvsBridgeStats {
  uint64_t steps = 0;
  uint32_t time_ms = 0;  // the last measurement's time
  int clients = 0;
  uint64_t welcomed = 0;
  uint64_t refused_clients = 0;  // not allowed or busy
  uint64_t dropped_clients = 0;  // left or dropped after Welcome
  uint64_t refused = 0;          // refused input, all kinds
  std::map<std::string, uint64_t> refused_by_kind;
};

class HlvsBridgeImpl;  // hlvs_bridge.cpp

// Binds every robot port on construction (std::invalid_argument for a bad allowlist); Run until stop() (polled) or a
// fatal DDS error (front_end_handle.h).
class HlvsBridge : public FrontEndHandle<HlvsBridgeImpl, HlvsBridgeOptions, HlvsBridgeStats> {
 public:
  using FrontEndHandle::FrontEndHandle;
  // Where images come from (owned by the caller, outliving the bridge); none by default. Call before Run.
  void SetCameraSource(hlvs::CameraSource* source);
  // The bound port of player n (1-based) of "red" or "blue"; 0 if none.
  uint16_t port(const std::string& team, int player) const;
};

}  // namespace turf
