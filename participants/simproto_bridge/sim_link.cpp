#include "participants/simproto_bridge/sim_link.h"

#include <turf/idl/ClockPubSubTypes.h>
#include <turf/idl/SimControlPubSubTypes.h>
#include <turf/idl/SslRobotPubSubTypes.h>
#include <turf/idl/SslVisionPubSubTypes.h>
#include <turf/idl/WorldStatePubSubTypes.h>

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <deque>
#include <map>
#include <mutex>
#include <set>
#include <thread>

#include "dds/request_id.h"

namespace turf {

class SimLink::Impl {
 public:
  explicit Impl(const dds::ParticipantOptions& options)
      : participant_(options),
        command_writers_{participant_.MakeWriter<idl::SslRobotCommandPubSubType>(dds::Topic::kSslCommandBlue),
                         participant_.MakeWriter<idl::SslRobotCommandPubSubType>(dds::Topic::kSslCommandYellow)},
        control_writer_(participant_.MakeWriter<idl::SimControlPubSubType>(dds::Topic::kControl)),
        reply_reader_(participant_.MakeReader<idl::SimControlReplyPubSubType>(dds::Topic::kControlReply, Wake())),
        feedback_readers_{
            participant_.MakeReader<idl::SslRobotFeedbackPubSubType>(dds::Topic::kSslFeedbackBlue, Wake()),
            participant_.MakeReader<idl::SslRobotFeedbackPubSubType>(dds::Topic::kSslFeedbackYellow, Wake())},
        field_reader_(participant_.MakeReader<idl::SslFieldPubSubType>(dds::Topic::kSslField, Wake())),
        clock_reader_(participant_.MakeReader<idl::ClockPubSubType>(dds::Topic::kClock, Wake())),
        world_reader_(participant_.MakeReader<idl::WorldStatePubSubType>(dds::Topic::kWorldState, Wake())),
        camera_reader_(participant_.MakeReader<idl::CameraFramePubSubType>(dds::Topic::kSslCamera, Wake())) {
    ready_.store(true);
  }

  ~Impl() { ready_.store(false); }

  dds::Participant& participant() { return participant_; }

  View Now() {
    std::lock_guard<std::mutex> lock(mutex_);
    PumpLocked();
    return view_;
  }

  void Command(const idl::SslRobotCommand& c) { command_writers_[c.team() == idl::TEAM_BLUE ? 0 : 1]->Write(c); }

  std::vector<std::optional<idl::SimControlReply>> Control(std::vector<idl::SimControl> requests,
                                                           std::chrono::milliseconds timeout) {
    std::vector<uint64_t> ids;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      for (idl::SimControl& r : requests) {
        r.client(participant_.options().name);
        r.request_id(++next_request_id_);
        ids.push_back(r.request_id());
        waiting_.insert(r.request_id());
      }
    }
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    // Requests are volatile: written before our writer has discovered
    // turf-sim's reader (turf-sim just seen, machine busy), they would be lost.
    while (control_writer_->Matched() == 0 && std::chrono::steady_clock::now() < deadline)
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    for (const idl::SimControl& r : requests) control_writer_->Write(r);
    std::vector<std::optional<idl::SimControlReply>> out(ids.size());
    std::unique_lock<std::mutex> lock(mutex_);
    auto all_in = [&] {
      PumpLocked();
      return std::all_of(ids.begin(), ids.end(), [&](uint64_t id) { return replies_.count(id) > 0; });
    };
    // Woken by every sample; also re-checks every 20 ms in case a wake-up came early.
    while (!all_in() && std::chrono::steady_clock::now() < deadline)
      changed_.wait_until(lock, std::min(deadline, std::chrono::steady_clock::now() + std::chrono::milliseconds(20)));
    for (size_t i = 0; i < ids.size(); ++i) {
      waiting_.erase(ids[i]);
      auto it = replies_.find(ids[i]);
      if (it == replies_.end()) continue;
      out[i] = it->second;
      replies_.erase(it);
    }
    return out;
  }

  uint64_t FrameCursor() {
    std::lock_guard<std::mutex> lock(mutex_);
    PumpLocked();
    return frames_received_;
  }

  std::vector<idl::CameraFrame> FramesSince(uint64_t cursor) {
    std::lock_guard<std::mutex> lock(mutex_);
    PumpLocked();
    const uint64_t first = frames_received_ - frames_.size();  // arrival number of frames_.front()
    std::vector<idl::CameraFrame> out;
    for (uint64_t i = std::max(cursor, first); i < frames_received_; ++i) out.push_back(frames_[i - first]);
    return out;
  }

  uint64_t Overflowed() const {
    uint64_t n = reply_reader_->Overflowed() + field_reader_->Overflowed() + clock_reader_->Overflowed() +
                 world_reader_->Overflowed() + camera_reader_->Overflowed();
    for (const auto& r : feedback_readers_) n += r->Overflowed();
    return n;
  }

 private:
  // Every reader's listener pumps all readers (once the Impl is complete) and wakes the waiters.
  std::function<void()> Wake() {
    return [this] {
      if (!ready_.load()) return;
      {
        std::lock_guard<std::mutex> lock(mutex_);
        PumpLocked();
      }
      changed_.notify_all();
    };
  }

  void PumpLocked() {
    if (!ready_.load()) return;
    if (field_reader_->Take(&fields_)) view_.field = fields_.back();
    if (clock_reader_->Take(&clocks_)) view_.clock = clocks_.back();
    if (world_reader_->Take(&worlds_)) view_.world = worlds_.back();
    for (auto& reader : feedback_readers_) {
      if (!reader->Take(&feedback_)) continue;
      for (const idl::SslRobotFeedback& f : feedback_) view_.contacts[{f.team(), f.id()}] = f.ball_contact();
    }
    if (camera_reader_->Take(&camera_inbox_)) {
      for (idl::CameraFrame& f : camera_inbox_) frames_.push_back(std::move(f));
      frames_received_ += camera_inbox_.size();
      while (frames_.size() > kMaxBufferedFrames) frames_.pop_front();
    }
    if (reply_reader_->Take(&reply_inbox_)) {
      for (const idl::SimControlReply& r : reply_inbox_)
        if (r.client() == participant_.options().name && waiting_.count(r.request_id()) > 0)
          replies_[r.request_id()] = r;
    }
  }

  // State first: DDS listeners may still run while the readers below are deleted.
  std::atomic<bool> ready_{false};
  std::mutex mutex_;
  std::condition_variable changed_;
  View view_;
  std::deque<idl::CameraFrame> frames_;  // the newest received, in arrival order
  uint64_t frames_received_ = 0;
  uint64_t next_request_id_ = dds::FirstRequestId();
  std::set<uint64_t> waiting_;
  std::map<uint64_t, idl::SimControlReply> replies_;
  std::vector<idl::SslField> fields_;
  std::vector<idl::Clock> clocks_;
  std::vector<idl::WorldState> worlds_;
  std::vector<idl::SslRobotFeedback> feedback_;
  std::vector<idl::CameraFrame> camera_inbox_;
  std::vector<idl::SimControlReply> reply_inbox_;

  dds::Participant participant_;
  std::unique_ptr<dds::Writer<idl::SslRobotCommandPubSubType>> command_writers_[2];
  std::unique_ptr<dds::Writer<idl::SimControlPubSubType>> control_writer_;
  std::unique_ptr<dds::Reader<idl::SimControlReplyPubSubType>> reply_reader_;
  std::unique_ptr<dds::Reader<idl::SslRobotFeedbackPubSubType>> feedback_readers_[2];
  std::unique_ptr<dds::Reader<idl::SslFieldPubSubType>> field_reader_;
  std::unique_ptr<dds::Reader<idl::ClockPubSubType>> clock_reader_;
  std::unique_ptr<dds::Reader<idl::WorldStatePubSubType>> world_reader_;
  std::unique_ptr<dds::Reader<idl::CameraFramePubSubType>> camera_reader_;
};

SimLink::SimLink(const dds::ParticipantOptions& options) : impl_(std::make_unique<Impl>(options)) {}
SimLink::~SimLink() = default;
std::string SimLink::TopicName(dds::Topic topic) const { return impl_->participant().TopicName(topic); }
const dds::ParticipantOptions& SimLink::options() const { return impl_->participant().options(); }
SimLink::View SimLink::Now() { return impl_->Now(); }
void SimLink::Command(const idl::SslRobotCommand& command) { impl_->Command(command); }
std::vector<std::optional<idl::SimControlReply>> SimLink::Control(std::vector<idl::SimControl> requests,
                                                                  std::chrono::milliseconds timeout) {
  return impl_->Control(std::move(requests), timeout);
}
uint64_t SimLink::FrameCursor() { return impl_->FrameCursor(); }
std::vector<idl::CameraFrame> SimLink::FramesSince(uint64_t cursor) { return impl_->FramesSince(cursor); }
uint64_t SimLink::Overflowed() const { return impl_->Overflowed(); }

}  // namespace turf
