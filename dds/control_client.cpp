#include "dds/control_client.h"

#include <fmt/format.h>

#include <algorithm>

#include "core/errors.h"
#include "dds/memory_bus.h"
#include "dds/request_id.h"

namespace turf::dds {

namespace {

// Matched-status changes wake nobody (the reader listens for data only):
// discovery is re-checked this often while waiting for it.
constexpr auto kDiscoveryPoll = std::chrono::milliseconds(5);
// Replies wake the waiters; this re-check only covers a wake-up that came early.
constexpr auto kReplyRecheck = std::chrono::milliseconds(20);

bool ValidReply(const idl::SimControlReply& r) {
  const auto op = static_cast<uint32_t>(r.op());
  const auto result = static_cast<uint32_t>(r.result());
  const auto error = static_cast<uint32_t>(r.error());
  if (op > static_cast<uint32_t>(idl::OP_SEEK)) return false;
  if (result > static_cast<uint32_t>(idl::RESULT_REJECTED)) return false;
  if (error >= static_cast<uint32_t>(Error::kCount)) return false;  // any code of the taxonomy
  // A success carries no error code, a refusal one.
  return (r.result() == idl::RESULT_OK) == (r.error() == idl::CONTROL_OK);
}

// Each ControlCallError's name and, but for kRefused (whose words are the reply's), what it means.
struct CallErrorText {
  ControlCallError error;
  const char* name;
  const char* description;
};
constexpr CallErrorText kCallErrorTexts[] = {
    {ControlCallError::kOk, "ok", "ok"},
    {ControlCallError::kRefused, "refused", "refused"},
    {ControlCallError::kNoServer, "no_server", "no turf-sim on the control topic"},
    {ControlCallError::kTimeout, "timeout", "turf-sim did not answer in time"},
    {ControlCallError::kStopped, "stopped", "stopped while waiting"},
};

const CallErrorText* TextOf(ControlCallError error) {
  for (const CallErrorText& t : kCallErrorTexts)
    if (t.error == error) return &t;
  return nullptr;
}

}  // namespace

const char* ControlCallErrorName(ControlCallError error) {
  const CallErrorText* t = TextOf(error);
  return t ? t->name : "unknown";
}

const char* ControlErrorName(idl::ControlError error) {
  // One table (core/errors.h): ControlError's constants are its IDL column.
  switch (error) {
#define TURF_ERROR_CASE(e, name, idl_constant, meaning) \
  case idl::idl_constant:                               \
    return name;
    TURF_ERRORS(TURF_ERROR_CASE)
#undef TURF_ERROR_CASE
  }
  return "unknown";
}

std::string ControlOutcome::Describe() const {
  if (error == ControlCallError::kRefused)
    return fmt::format("refused ({}): {}", ControlErrorName(code()), reply ? reply->reason() : std::string());
  const CallErrorText* t = TextOf(error);
  return t ? t->description : "unknown";
}

ControlClient::ControlClient(Bus& bus, std::string name, std::function<void()> on_reply)
    : name_(std::move(name)),
      on_reply_(std::move(on_reply)),
      next_id_(dynamic_cast<MemoryBus*>(&bus) != nullptr ? InProcessFirstRequestId() : FirstRequestId()) {
  writer_ = bus.MakeWriter<idl::SimControlPubSubType>(Topic::kControl);
  reader_ = bus.MakeReader<idl::SimControlReplyPubSubType>(Topic::kControlReply, [this] {
    if (!ready_.load()) return;
    TakeReplies();
    if (on_reply_) on_reply_();
  });
  ready_.store(true);
  TakeReplies();  // whatever arrived before ready_
}

ControlClient::~ControlClient() {
  ready_.store(false);
  reader_.reset();  // no listener runs past here
}

bool ControlClient::ServerMatched() const { return writer_->Matched() > 0 && reader_->Matched() > 0; }

// Fast DDS calls our reader's listener (which takes mutex_) with its own locks
// held: no DDS call may be made while holding mutex_ (Matched, Write, Take).
bool ControlClient::WaitForServer(SteadyClock::time_point deadline, const StopFn& stop) {
  while (!ServerMatched()) {
    if (SteadyClock::now() >= deadline || (stop && stop())) return false;
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait_until(lock, std::min(deadline, SteadyClock::now() + kDiscoveryPoll));
  }
  return true;
}

ControlOutcome ControlClient::Call(idl::SimControl request, std::chrono::milliseconds timeout, const StopFn& stop) {
  std::vector<idl::SimControl> one;
  one.push_back(std::move(request));
  return CallAll(std::move(one), timeout, stop).front();
}

std::vector<ControlOutcome> ControlClient::CallAll(std::vector<idl::SimControl> requests,
                                                   std::chrono::milliseconds timeout, const StopFn& stop) {
  const auto deadline = SteadyClock::now() + timeout;
  std::vector<ControlOutcome> out(requests.size());
  if (!WaitForServer(deadline, stop)) {
    const bool stopped = stop && stop();
    for (ControlOutcome& o : out) o.error = stopped ? ControlCallError::kStopped : ControlCallError::kNoServer;
    return out;
  }
  std::vector<uint64_t> ids;
  for (idl::SimControl& r : requests) ids.push_back(Register(r, deadline, {}));
  for (const idl::SimControl& r : requests) Write(r);
  for (size_t i = 0; i < ids.size(); ++i) out[i] = Wait(ids[i], stop);
  return out;
}

uint64_t ControlClient::Send(idl::SimControl request, std::chrono::milliseconds timeout, Callback done) {
  const uint64_t id = Register(request, SteadyClock::now() + timeout, std::move(done));
  Write(request);
  return id;
}

uint64_t ControlClient::Register(idl::SimControl& request, SteadyClock::time_point deadline, Callback done) {
  std::lock_guard<std::mutex> lock(mutex_);
  const uint64_t id = next_id_++;
  request.client(name_);
  request.request_id(id);
  if (outstanding_.size() >= kMaxOutstanding) {  // the oldest is given up: its callback hears so (Dispatch)
    auto oldest = outstanding_.begin();
    if (oldest->second.done)
      given_up_.emplace_back(
          std::move(oldest->second.done),
          oldest->second.outcome.value_or(ControlOutcome{oldest->first, ControlCallError::kTimeout, std::nullopt}));
    outstanding_.erase(oldest);
  }
  Outstanding& o = outstanding_[id];
  o.deadline = deadline;
  o.done = std::move(done);
  return id;
}

// Only the writer's match is asked for: the reply reader is durable
// (TRANSIENT_LOCAL), so a reply written before it matched still reaches it.
void ControlClient::Write(const idl::SimControl& request) {
  if (writer_->Matched() > 0 && writer_->Write(request)) return;
  std::lock_guard<std::mutex> lock(mutex_);
  auto it = outstanding_.find(request.request_id());
  if (it != outstanding_.end() && !it->second.outcome)
    it->second.outcome = ControlOutcome{request.request_id(), ControlCallError::kNoServer, std::nullopt};
}

void ControlClient::TakeReplies() {
  std::vector<idl::SimControlReply> inbox;
  if (!reader_ || !reader_->Take(&inbox)) return;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    for (const idl::SimControlReply& r : inbox) {
      if (r.client() != name_) continue;  // another client's: not ours to judge
      if (!ValidReply(r)) {
        bad_.fetch_add(1);
        continue;
      }
      auto it = outstanding_.find(r.request_id());
      if (it == outstanding_.end() || it->second.outcome) {
        stray_.fetch_add(1);
        continue;
      }
      it->second.outcome = ControlOutcome{
          r.request_id(), r.result() == idl::RESULT_OK ? ControlCallError::kOk : ControlCallError::kRefused, r};
    }
  }
  changed_.notify_all();
}

void ControlClient::ExpireLocked(SteadyClock::time_point now) {
  for (auto& [id, o] : outstanding_) {
    if (!o.outcome && now >= o.deadline) o.outcome = ControlOutcome{id, ControlCallError::kTimeout, std::nullopt};
  }
}

size_t ControlClient::Dispatch() {
  TakeReplies();
  std::vector<std::pair<Callback, ControlOutcome>> due;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    ExpireLocked(SteadyClock::now());
    due.swap(given_up_);
    for (auto it = outstanding_.begin(); it != outstanding_.end();) {
      if (it->second.done && it->second.outcome) {
        due.emplace_back(std::move(it->second.done), std::move(*it->second.outcome));
        it = outstanding_.erase(it);
      } else {
        ++it;
      }
    }
  }
  for (auto& [done, outcome] : due) done(outcome);
  return due.size();
}

std::optional<ControlOutcome> ControlClient::Peek(uint64_t request_id) {
  TakeReplies();
  std::lock_guard<std::mutex> lock(mutex_);
  ExpireLocked(SteadyClock::now());
  auto it = outstanding_.find(request_id);
  if (it == outstanding_.end() || it->second.done) return std::nullopt;
  return it->second.outcome;
}

std::optional<ControlOutcome> ControlClient::TryTake(uint64_t request_id) {
  TakeReplies();
  std::lock_guard<std::mutex> lock(mutex_);
  ExpireLocked(SteadyClock::now());
  auto it = outstanding_.find(request_id);
  if (it == outstanding_.end() || it->second.done || !it->second.outcome) return std::nullopt;
  std::optional<ControlOutcome> out = std::move(it->second.outcome);
  outstanding_.erase(it);
  return out;
}

void ControlClient::Forget(uint64_t request_id) {
  std::lock_guard<std::mutex> lock(mutex_);
  auto it = outstanding_.find(request_id);
  if (it == outstanding_.end()) return;
  if (it->second.outcome) {
    outstanding_.erase(it);
  } else {
    it->second.done = [](const ControlOutcome&) {};  // Dispatch() drops it once settled
  }
}

ControlOutcome ControlClient::Wait(uint64_t request_id, const StopFn& stop) {
  TakeReplies();
  std::unique_lock<std::mutex> lock(mutex_);
  while (true) {
    const auto now = SteadyClock::now();
    ExpireLocked(now);
    auto it = outstanding_.find(request_id);
    if (it == outstanding_.end() || it->second.done) return ControlOutcome{request_id, ControlCallError::kTimeout, {}};
    if (it->second.outcome) {
      ControlOutcome out = std::move(*it->second.outcome);
      outstanding_.erase(it);
      return out;
    }
    if (stop && stop()) {
      outstanding_.erase(it);
      return ControlOutcome{request_id, ControlCallError::kStopped, std::nullopt};
    }
    changed_.wait_until(lock, std::min(it->second.deadline, now + kReplyRecheck));
  }
}

}  // namespace turf::dds
