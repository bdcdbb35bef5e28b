// The lockstep DDS link to turf-sim's legged scene shared by the lockstep front-ends (participants/lockstep_front_end/:
// SimSpark, RCSSServerMJ and HLVS): the control client, the scene, clock and robots/state readers, switching turf-sim
// to lockstep, moves, and one step with waiting for the whole robots/state frame after it.
//
// Writes: control (SimControl: OP_SET_TIME_MODE, OP_TELEPORT_*, OP_STEP with joint commands).
// Reads:  legged/scene (latched), robots/state (every robot and the ball in one sample per frame), clock,
//         control_reply.
#pragma once

#include <turf/idl/ClockPubSubTypes.h>
#include <turf/idl/JointsPubSubTypes.h>
#include <turf/idl/SimControlPubSubTypes.h>

#include <Eigen/Geometry>
#include <chrono>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/pinned.h"
#include "dds/control_client.h"
#include "dds/participant.h"
#include "participants/common/stalled_authentication.h"
#include "participants/common/wakeup.h"

namespace turf {

class LeggedLockstep : Pinned {
 public:
  using Clock = std::chrono::steady_clock;
  using StopFn = std::function<bool()>;

  // On `bus` (`own` null: a bus that outlives the link). `client` goes into every control request; with
  // `need_force` a frame is whole only with every robot's force sensors too.
  LeggedLockstep(std::unique_ptr<dds::Participant> own, dds::Bus& bus, const char* client, bool need_force);
  ~LeggedLockstep();

  std::string TopicName(dds::Topic t) const { return bus_.TopicName(t); }
  std::string DescribeBus() const { return bus_.Describe(); }

  // Waits for turf-sim's scene, switches it to lockstep, and waits for the state of every robot of the scene (in
  // scene order); false on timeout (logged as an error) or stop. Logs what it waits for. On a participant of its
  // own, a DDS authentication that stalls meanwhile restarts the process (stalled_authentication.h: RequestRestart,
  // so `stop` of a participant's main answers true).
  bool Attach(std::chrono::milliseconds timeout, const StopFn& stop);
  // Moves, answered before the step; their refusals are reported by the next Step (late ones a step later).
  void SendMove(const std::string& robot, const Eigen::Vector3d& position, const Eigen::Quaterniond& orientation,
                bool reset_joints, std::chrono::milliseconds timeout);
  void SendBall(const Eigen::Vector3d& position, const Eigen::Vector3d& velocity, std::chrono::milliseconds timeout);
  // Sends `step` (OP_STEP of `steps` physics steps) and waits for the whole frame after it; false (error set) when
  // turf-sim refused the step or did not answer within `timeout`. Refused moves go to `warnings`.
  bool Step(idl::SimControl step, uint32_t steps, std::chrono::milliseconds timeout, const StopFn& stop,
            std::string* error, std::vector<std::string>* warnings);

  const idl::LeggedSceneInfo& scene_info() const { return *scene_info_; }
  const idl::LeggedState& state() const { return *state_now_; }  // after WaitForFrame or Step
  uint64_t frame() const { return frame_; }
  double step_s() const { return step_s_; }
  uint64_t Overflowed() const;

  static idl::Vec3 V3(const Eigen::Vector3d& v);

 private:
  // Attach's steps; false with `error` set.
  bool TryAttach(std::chrono::milliseconds timeout, const StopFn& stop, std::string* error);
  // Waits for turf-sim's scene and its control endpoints; false on timeout or stop.
  bool WaitForScene(Clock::time_point deadline, const StopFn& stop);
  // Asks for lockstep, again every 0.5 s until answered (a request or reply can miss an endpoint turf-sim has not
  // discovered yet; the request is idempotent). An accepted answer's frame becomes the current frame.
  dds::ControlOutcome SwitchToLockstep(Clock::time_point deadline, const StopFn& stop);
  // Waits for the clock and the whole state of `robots` at the current frame; `robots` are the frame's robots.
  bool WaitForFrame(const std::vector<std::string>& robots, Clock::time_point deadline, const StopFn& stop);
  std::function<void()> Wake();
  void Drain();
  // Polls until done() or the deadline; false on timeout or stop.
  bool WaitFor(const std::function<bool()>& done, Clock::time_point deadline, const StopFn& stop);
  // The newest state is of `frame` and has every robot, whole.
  bool Complete(uint64_t frame) const;

  const bool need_force_;
  Wakeup wakeup_;
  std::unique_ptr<dds::Participant> own_;
  StalledAuthenticationRestart restart_;  // own_'s stalls while Attach waits
  dds::Bus& bus_;
  dds::ControlClient control_;
  dds::ReaderOf<dds::Topic::kLeggedScene> scene_;
  dds::ReaderOf<dds::Topic::kClock> clock_;
  dds::ReaderOf<dds::Topic::kRobotsState> state_;
  std::vector<idl::LeggedSceneInfo> scene_in_;
  std::vector<idl::Clock> clock_in_;
  std::vector<idl::LeggedState> state_in_;
  std::optional<idl::LeggedSceneInfo> scene_info_;
  std::optional<idl::LeggedState> state_now_;
  std::vector<std::string> move_warnings_;  // refused moves, reported with the next step
  std::vector<std::string> robots_;
  uint64_t frame_ = 0;
  double step_s_ = 0.0;
};

}  // namespace turf
