// Which clock the SSL-Vision times are in, and the rules every sent time
// obeys. Pure: the caller passes the wall clock and the run epoch in.
//
//   kRun (default): the run epoch (turf-sim's Clock.run_epoch_unix_ns: the Unix
//     time of sim time 0 of this run) plus the simulation time. Unix-looking,
//     yet exact at any speed and under load; a reset advances the epoch by the
//     sim time reached, so the times never go back. t_capture = epoch +
//     capture_time_ns, t_sent = epoch + sent_time_ns.
//   kUnix (what real SSL-Vision sends): t_sent is the Unix time at sending,
//     passed in by the caller; t_capture = t_sent minus the frame's simulated
//     latency (sent_time_ns - capture_time_ns).
//   kSim: seconds of simulation time since the scene started (or last reset).
//
// Guarantees: every time is > 0 and t_sent >= t_capture. A frame that would
// break them (capture at or before sim time 0, sent before captured, a wall
// clock that is not a positive number, no plausible run epoch) is refused with
// a named error.
//
// Resets in kRun mode: the epoch arrives on the clock topic, the frames on
// another, so a frame of the old timeline may be taken after the new epoch, or
// the new timeline's first frame before it. Each stream (a camera, the world
// state) therefore keeps the epoch its timeline started with, and moves to the
// next epoch only when its own times go back. A stream that went back before
// the new epoch arrived is refused (kNoEpoch) until it arrives.
#pragma once

#include <cstdint>
#include <deque>
#include <map>
#include <optional>
#include <string>

#include "codecs/ssl_vision/detection.h"
#include "codecs/ssl_vision/errors.h"

namespace turf::vision {

enum class ClockMode : uint8_t { kRun, kUnix, kSim };

const char* ClockModeName(ClockMode mode);                         // "run", "unix", "sim"
std::optional<ClockMode> ParseClockMode(const std::string& name);  // inverse of ClockModeName

// Plausible run epochs, in Unix ns: 2000-01-01 to 2200-01-01. Anything else
// (0, negative, a clock far off) is not a run epoch but garbage.
inline constexpr int64_t kMinRunEpochNs = 946'684'800'000'000'000;
inline constexpr int64_t kMaxRunEpochNs = 7'258'118'400'000'000'000;

// kOk, or kBadEpoch for an epoch outside [kMinRunEpochNs, kMaxRunEpochNs].
VisionError CheckRunEpoch(int64_t run_epoch_unix_ns);

class WireClock {
 public:
  explicit WireClock(ClockMode mode = ClockMode::kRun) : mode_(mode) {}
  ClockMode mode() const { return mode_; }

  // A Clock sample's run epoch. An implausible one is refused (kBadEpoch) and
  // the last good one kept. Accepted in every mode; only kRun uses it.
  VisionError AddRunEpoch(int64_t run_epoch_unix_ns);
  // The newest accepted run epoch, if any.
  std::optional<int64_t> run_epoch_ns() const;

  // A camera frame's t_capture and t_sent, following the camera's timeline
  // across resets (kRun; other modes: as ForFrame). `unix_now` (seconds since
  // the Unix epoch, at sending) is used in kUnix mode only.
  VisionError ForCamera(uint32_t camera_id, int64_t capture_time_ns, int64_t sent_time_ns, double unix_now,
                        FrameTimes* out);
  // A tracked frame's timestamp, following the world state's timeline (kRun:
  // epoch + sim time; kUnix: `unix_now`; kSim: sim time, refused at 0).
  VisionError ForWorldState(int64_t sim_time_ns, double unix_now, double* out);

  // Stateless forms: kRun uses the newest epoch, whatever timeline the time is
  // from (right only without resets; the sync protocol uses kSim).
  VisionError ForFrame(int64_t capture_time_ns, int64_t sent_time_ns, double unix_now, FrameTimes* out) const;
  VisionError ForState(int64_t sim_time_ns, double unix_now, double* out) const;

 private:
  // Where one stream (camera or world state) is: the sequence number of its
  // timeline's epoch and its newest time; `waiting` after it went back before
  // a newer epoch arrived.
  struct Stream {
    uint64_t epoch_seq = 0;
    int64_t last_ns = 0;
    bool waiting = false;
  };
  static constexpr size_t kKeptEpochs = 16;  // resets remembered
  static constexpr size_t kMaxStreams = 64;  // camera ids tracked (untrusted input)

  VisionError EpochFor(Stream* stream, bool known, int64_t time_ns, bool equal_is_new, int64_t* epoch_ns) const;
  VisionError RunTimes(int64_t epoch_ns, int64_t capture_time_ns, int64_t sent_time_ns, FrameTimes* out) const;

  ClockMode mode_;
  std::deque<int64_t> epochs_;  // distinct epochs in arrival order, newest last
  uint64_t first_seq_ = 0;      // sequence number of epochs_.front()
  std::map<uint32_t, Stream> cameras_;
  std::optional<Stream> state_;
};

}  // namespace turf::vision
