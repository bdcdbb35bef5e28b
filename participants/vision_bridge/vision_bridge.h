// turf-vision-bridge's node: turf's SSL camera topics out as SSL-Vision UDP.
//
// Subscribes (topic names <prefix>/..., QoS profiles in configs/qos/turf_qos.xml):
//   ssl/camera   CameraFrame  one per camera per capture (60 Hz of sim time)
//   ssl/field    SslField     latched: field, ball model, cameras
//   world_state  WorldState   only with `tracked` (100 Hz of sim time)
//   clock        Clock        only with ClockMode::kRun (the default): the run
//                             epoch, with every world state
// Sends (UDP, multicast or unicast):
//   address:port                  one SSL_WrapperPacket with the detection per
//                                 camera frame; a geometry-only wrapper once the
//                                 field is known and every `geometry_every`
//                                 capture rounds (default 224.5.23.2:10020)
//   tracked_address:tracked_port  one TrackerWrapperPacket per world state
//                                 (default 224.5.23.2:10010, only with `tracked`)
// Times (codecs/ssl_vision/timestamps.h): by default turf-sim's run epoch
// plus simulation time, in Unix seconds, so every bridge and a restarted one
// stamp alike and the times follow the simulation at any speed; frames that
// arrive before the epoch is known are dropped and counted (`no_epoch`).
// ClockMode::kUnix gives the wall clock at sending (the cameras of one capture
// round share one reading), kSim simulation seconds. Every DDS sample is
// untrusted: one that fails the codec's checks (a garbage run epoch included)
// is dropped, counted per kind and logged at a limited rate. Nothing is sent
// until turf-sim is there.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include "codecs/ssl_vision/timestamps.h"
#include "core/pinned.h"
#include "participants/common/participant_options.h"

namespace turf {

struct VisionBridgeOptions : ParticipantOptions {
  VisionBridgeOptions() { name = "turf-vision-bridge"; }
  std::string address = "224.5.23.2";  // multicast group or unicast address
  uint16_t port = 10020;
  std::string interface_ip;  // multicast interface address; empty: the system's choice
  int ttl = 1;               // multicast hops
  int geometry_every = 120;  // capture rounds between geometry packets; 0: only when the field changes
  vision::ClockMode clock = vision::ClockMode::kRun;
  bool tracked = false;
  std::string tracked_address = "224.5.23.2";
  uint16_t tracked_port = 10010;
  std::string tracked_uuid;  // empty: a random one per run
};

struct VisionBridgeStats {
  uint64_t detections_sent = 0;
  uint64_t geometry_sent = 0;
  uint64_t tracked_sent = 0;
  uint64_t rejected = 0;     // dropped samples of every kind
  uint64_t send_errors = 0;  // datagrams the socket refused
  uint64_t no_epoch = 0;     // frames not sent: no run epoch known for them (yet)
};

class VisionBridge : Pinned {
 public:
  // Throws std::invalid_argument for a bad address or option, std::runtime_error
  // if the socket or the DDS participant cannot be created.
  explicit VisionBridge(VisionBridgeOptions options);
  ~VisionBridge();

  // Runs until `stop()` answers true (checked at least every 50 ms).
  void Run(const std::function<bool()>& stop);
  VisionBridgeStats Stats() const;
  // Drops of one kind, e.g. "camera.not_finite", "field.non_positive_size",
  // "clock.bad_epoch", "camera.no_epoch".
  uint64_t Rejected(const std::string& kind) const;

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace turf
