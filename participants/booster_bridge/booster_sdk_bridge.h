// The Booster Robotics SDK's low-level DDS topics for every simulated T1 and K1 (issue 15; facts:
// shared/protocols/booster-sdk-dds.md), so that a robot program written against the SDK runs unchanged. Served from
// turf-sim's process (`turf-sim --booster-sdk`) on its in-memory bus, or from any process on a dds::Bus:
//  - rt/low_state (LowState_) at every sensor frame of the scene (rates.joint_state_hz), from the robot's frame on
//    robots/state (the scene's sensor realism applies: value noise, no link delay);
//  - rt/joint_ctrl (LowCmd_) into PD commands on robots/joint_command (codecs/booster/low_cmd.h). turf-sim's one
//    validator checks them; a refused message changes nothing (counted, logged) and the robot holds its last
//    accepted command, as every PD target holds until replaced;
//  - rt/odometer_state (Odometer_): the base's x, y and yaw relative to its pose at the first frame (ground truth:
//    the SDK's odometry is its walking controller's, which turf does not run);
//  - rt/fall_down (FallDownState_): HAS_FALLEN while the trunk tilts more than 60 deg from upright, IS_READY else.
// The robot is in Custom mode from the start (no loco RPC): joint_ctrl drives it, whatever the weights.
// Robots: every robot of the scene whose joints are a T1's or a K1's (codecs/booster/robots.h), each on a DDS domain
// of its own, the first on `domain` (0, as the SDK's examples), the next on domain + 1, in scene order: a program
// picks its robot by domain, as on a real robot network.
// Untrusted input: a LowCmd whose source timestamp is older than command_timeout (stale) or further ahead of this
// host's clock than that (future), malformed or out of range is
// refused whole, counted by kind ("joint_ctrl.<error>") and logged at most once a second per kind.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/pinned.h"
#include "dds/bus_fwd.h"

namespace turf {

struct BoosterSdkOptions {
  int domain = 0;                                  // the first Booster robot's DDS domain
  int turf_domain = -1;                            // turf's own (a robot's on it is warned of); -1: unknown
  std::chrono::milliseconds command_timeout{500};  // a LowCmd older than this (source timestamp) is refused
};

struct BoosterSdkStats {
  uint64_t states = 0;    // LowState samples published
  uint64_t commands = 0;  // LowCmd samples passed on to turf-sim
  uint64_t refused = 0;
  std::map<std::string, uint64_t> refused_by_kind;
};

class BoosterSdkBridge : Pinned {
 public:
  // On `bus` (turf's topics); the bus must outlive the bridge.
  BoosterSdkBridge(BoosterSdkOptions options, dds::Bus& bus);
  ~BoosterSdkBridge();

  // Until stop() (polled every 50 ms).
  void Run(const std::function<bool()>& stop);

  BoosterSdkStats Stats() const;
  // The robots served so far ("t1 (T1) on domain 0"), known from turf-sim's first frame.
  std::vector<std::string> Robots() const;

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace turf
