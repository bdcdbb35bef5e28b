// The one client of turf-sim's control plane: requests on <prefix>/control
// (SimControl), replies on <prefix>/control_reply (SimControlReply).
//
// - Request ids: the client names every request (`client` = its name) and
//   numbers it from a per-process random start (dds/request_id.h), so replies
//   a restarted client's predecessor left on the durable reply topic never
//   match (on an in-process MemoryBus, where there is no predecessor, from a
//   fixed start: a run's recorded requests and replies are the same bytes). A reply is matched by (client, request_id);
//   one with our name and an id we are not waiting for, or with values out of range, is counted (stray_replies(),
//   bad_replies()) and dropped.
// - Discovery: turf-sim is there when our control writer and reply reader are
//   both matched (ServerMatched()). The blocking forms wait for it until their
//   deadline and fail with kNoServer if it never came.
// - Errors are values: ControlCallError says whether a reply came and what it
//   said; a refusal keeps the reply (its `error` code and `reason`).
// - Forms: Call()/CallAll() block; Send() returns at once and its callback runs
//   in Dispatch() on the caller's thread when the reply arrives or the deadline
//   passes; Peek()/TryTake()/Wait() collect an uncallbacked Send()'s outcome.
//
// Thread-safety: every method may be called from any thread; the replies are
// taken on the bus's delivery thread (Fast DDS's listener, or the writer's on a
// MemoryBus) and kept under one mutex, which is never held across a bus call
// (Fast DDS holds its own locks while it calls the listener, so the reverse
// order would deadlock). Callbacks run only inside Dispatch(), never on a
// delivery thread, and without the mutex held (a callback may Send()).
// `on_reply` (constructor) runs on the delivery thread: use it only to wake a
// loop.
#pragma once

#include <turf/idl/SimControlPubSubTypes.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/pinned.h"
#include "dds/bus.h"

namespace turf::dds {

enum class ControlCallError : uint8_t {
  kOk,        // turf-sim did it (reply RESULT_OK)
  kRefused,   // turf-sim refused it: reply->error() and reply->reason() say why
  kNoServer,  // no turf-sim matched by the deadline (or the write failed): nothing was sent
  kTimeout,   // sent, but no reply by the deadline
  kStopped,   // the caller's stop() answered true while waiting
};
const char* ControlCallErrorName(ControlCallError error);
// The name of a reply's error code ("not_finite"), "unknown" past the enum.
const char* ControlErrorName(idl::ControlError error);

struct ControlOutcome {
  uint64_t request_id = 0;
  ControlCallError error = ControlCallError::kTimeout;
  std::optional<idl::SimControlReply> reply;  // set for kOk and kRefused
  bool ok() const { return error == ControlCallError::kOk; }
  // The refusal's code (CONTROL_OK unless kRefused).
  idl::ControlError code() const { return reply ? reply->error() : idl::CONTROL_OK; }
  // One line for logs and protocol errors: the reason, or what went wrong.
  std::string Describe() const;
};

class ControlClient : Pinned {
 public:
  using SteadyClock = std::chrono::steady_clock;
  using Callback = std::function<void(const ControlOutcome&)>;
  using StopFn = std::function<bool()>;
  // Past this the oldest request is given up: a callback of it runs at the next Dispatch with kTimeout (or the
  // outcome it had); a waiting Call of it ends as a timeout.
  static constexpr size_t kMaxOutstanding = 4096;

  // Makes the control writer and the reply reader on `bus` (a dds::Participant,
  // or a dds::MemoryBus shared with turf-sim's node; it must outlive the client).
  // `name` goes into every request's `client`.
  ControlClient(Bus& bus, std::string name, std::function<void()> on_reply = {});
  ~ControlClient();

  const std::string& name() const { return name_; }
  // turf-sim's control reader and reply writer are both matched.
  bool ServerMatched() const;
  // Waits for ServerMatched() until `deadline` (or stop()); false if it did not come.
  bool WaitForServer(SteadyClock::time_point deadline, const StopFn& stop = {});

  // Blocking: waits for the server, sends, waits for the reply; all by `timeout`.
  ControlOutcome Call(idl::SimControl request, std::chrono::milliseconds timeout, const StopFn& stop = {});
  // The same for several requests, sent in order; one outcome each, in order.
  std::vector<ControlOutcome> CallAll(std::vector<idl::SimControl> requests, std::chrono::milliseconds timeout,
                                      const StopFn& stop = {});

  // Async: numbers and writes the request now and returns its id. If no server
  // is matched, nothing is written and the outcome is kNoServer at once. With a
  // callback, Dispatch() runs it once with the outcome; without, the outcome
  // waits for TryTake()/Wait() (kTimeout once `timeout` has passed).
  uint64_t Send(idl::SimControl request, std::chrono::milliseconds timeout, Callback done = {});
  // Runs the callbacks of requests that were answered or timed out; returns how many.
  size_t Dispatch();
  // The outcome of an uncallbacked request once settled, left in place.
  std::optional<ControlOutcome> Peek(uint64_t request_id);
  // The same, and the request is then forgotten.
  std::optional<ControlOutcome> TryTake(uint64_t request_id);
  // Nobody will take request `request_id`: dropped once settled.
  void Forget(uint64_t request_id);
  // Blocks until request `request_id` is settled (or stop()), then takes it.
  ControlOutcome Wait(uint64_t request_id, const StopFn& stop = {});

  // Replies with our name but an id we are not waiting for (late, duplicated,
  // or a predecessor's); replies whose values are out of range.
  uint64_t stray_replies() const { return stray_.load(); }
  uint64_t bad_replies() const { return bad_.load(); }
  uint64_t Overflowed() const { return reader_->Overflowed(); }

 private:
  struct Outstanding {
    SteadyClock::time_point deadline;
    Callback done;
    std::optional<ControlOutcome> outcome;  // set once settled
  };

  void TakeReplies();  // DDS thread or caller; takes mutex_ after the DDS take
  void ExpireLocked(SteadyClock::time_point now);
  // Numbers the request and waits for its outcome; then Write() sends it (outside mutex_).
  uint64_t Register(idl::SimControl& request, SteadyClock::time_point deadline, Callback done);
  void Write(const idl::SimControl& request);

  const std::string name_;
  std::function<void()> on_reply_;
  std::atomic<bool> ready_{false};  // false while the reader may run before the members exist
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  uint64_t next_id_;
  std::map<uint64_t, Outstanding> outstanding_;                // by request id (ids grow: begin() is the oldest)
  std::vector<std::pair<Callback, ControlOutcome>> given_up_;  // past kMaxOutstanding, for the next Dispatch
  std::atomic<uint64_t> stray_{0};
  std::atomic<uint64_t> bad_{0};
  std::unique_ptr<Writer<idl::SimControlPubSubType>> writer_;
  std::unique_ptr<Reader<idl::SimControlReplyPubSubType>> reader_;
};

}  // namespace turf::dds
