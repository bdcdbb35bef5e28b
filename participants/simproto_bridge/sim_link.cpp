#include "participants/simproto_bridge/sim_link.h"

#include <turf/idl/ClockPubSubTypes.h>
#include <turf/idl/SimControlPubSubTypes.h>
#include <turf/idl/SslRobotPubSubTypes.h>
#include <turf/idl/SslVisionPubSubTypes.h>
#include <turf/idl/WorldStatePubSubTypes.h>

#include <algorithm>
#include <atomic>
#include <deque>
#include <mutex>
#include <optional>

namespace turf {

class SimLink::Impl {
 public:
  // `own` null: on `bus`, which outlives the link.
  Impl(std::unique_ptr<dds::Participant> own, dds::Bus& bus, const std::string& name)
      : own_(std::move(own)),
        bus_(bus),
        command_writers_{bus_.MakeWriter<idl::SslRobotCommandPubSubType>(dds::Topic::kSslCommandBlue),
                         bus_.MakeWriter<idl::SslRobotCommandPubSubType>(dds::Topic::kSslCommandYellow)},
        control_(bus_, name),
        feedback_readers_{bus_.MakeReader<idl::SslRobotFeedbackPubSubType>(dds::Topic::kSslFeedbackBlue, Wake()),
                          bus_.MakeReader<idl::SslRobotFeedbackPubSubType>(dds::Topic::kSslFeedbackYellow, Wake())},
        field_reader_(bus_.MakeReader<idl::SslFieldPubSubType>(dds::Topic::kSslField, Wake())),
        clock_reader_(bus_.MakeReader<idl::ClockPubSubType>(dds::Topic::kClock, Wake())),
        world_reader_(bus_.MakeReader<idl::WorldStatePubSubType>(dds::Topic::kWorldState, Wake())),
        camera_reader_(bus_.MakeReader<idl::CameraFramePubSubType>(dds::Topic::kSslCamera, Wake())) {
    ready_.store(true);
  }

  ~Impl() { ready_.store(false); }

  dds::Bus& bus() { return bus_; }
  // On a bus of turf-sim's process: nothing to authenticate.
  dds::Authentications AuthenticationsNow() const { return own_ ? own_->AuthenticationsNow() : dds::Authentications{}; }

  View Now() {
    std::lock_guard<std::mutex> lock(mutex_);
    PumpLocked();
    return view_;
  }

  void Command(const idl::SslRobotCommand& c) { command_writers_[c.team() == idl::TEAM_BLUE ? 0 : 1]->Write(c); }

  // Requests are volatile: the client waits until turf-sim's reader is matched.
  std::vector<dds::ControlOutcome> Control(std::vector<idl::SimControl> requests, std::chrono::milliseconds timeout,
                                           const dds::ControlClient::StopFn& stop) {
    return control_.CallAll(std::move(requests), timeout, stop);
  }

  uint64_t FrameCursor() {
    std::lock_guard<std::mutex> lock(mutex_);
    PumpLocked();
    frames_.clear();  // older ones nobody wants
    wanted_from_ = frames_received_;
    return frames_received_;
  }

  std::vector<std::shared_ptr<const idl::CameraFrame>> FramesSince(uint64_t cursor) {
    std::lock_guard<std::mutex> lock(mutex_);
    PumpLocked();
    const uint64_t first = frames_received_ - frames_.size();  // arrival number of frames_.front()
    std::vector<std::shared_ptr<const idl::CameraFrame>> out;
    const uint64_t from = std::max(cursor, first);
    out.reserve(frames_received_ > from ? frames_received_ - from : 0);
    for (uint64_t i = from; i < frames_received_; ++i) out.push_back(frames_[i - first]);
    frames_.clear();
    wanted_from_.reset();
    return out;
  }

  uint64_t Overflowed() const {
    uint64_t n = control_.Overflowed() + field_reader_->Overflowed() + clock_reader_->Overflowed() +
                 world_reader_->Overflowed() + camera_reader_->Overflowed();
    for (const auto& r : feedback_readers_) n += r->Overflowed();
    return n;
  }

 private:
  // Every reader's listener pumps all readers (once the Impl is complete).
  std::function<void()> Wake() {
    return [this] {
      if (!ready_.load()) return;
      std::lock_guard<std::mutex> lock(mutex_);
      PumpLocked();
    };
  }

  void PumpLocked() {
    if (!ready_.load()) return;
    if (field_reader_->Take(&fields_)) view_.field = std::make_shared<const idl::SslField>(std::move(fields_.back()));
    if (clock_reader_->Take(&clocks_)) view_.clock = clocks_.back();
    if (world_reader_->Take(&worlds_)) view_.world = std::make_shared<const idl::WorldState>(std::move(worlds_.back()));
    bool contacts_changed = false;
    for (auto& reader : feedback_readers_) {
      if (!reader->Take(&feedback_)) continue;
      for (const idl::SslRobotFeedback& f : feedback_) {
        const simproto::ContactMap::key_type robot{f.team(), f.id()};
        auto it = contacts_.find(robot);
        if (it != contacts_.end() && it->second == f.ball_contact()) continue;
        contacts_[robot] = f.ball_contact();
        contacts_changed = true;
      }
    }
    if (contacts_changed) view_.contacts = std::make_shared<const simproto::ContactMap>(contacts_);
    if (camera_reader_->Take(&camera_inbox_)) {
      frames_received_ += camera_inbox_.size();
      if (!wanted_from_) return;  // no frame is kept while no one has a cursor (they go with the next Take)
      for (idl::CameraFrame& f : camera_inbox_)
        frames_.push_back(std::make_shared<const idl::CameraFrame>(std::move(f)));
      while (frames_.size() > kMaxBufferedFrames) frames_.pop_front();
    }
  }

  // State first: DDS listeners may still run while the readers below are deleted.
  std::atomic<bool> ready_{false};
  std::mutex mutex_;
  View view_;
  simproto::ContactMap contacts_;                               // view_.contacts' source
  std::deque<std::shared_ptr<const idl::CameraFrame>> frames_;  // the newest received, in arrival order (shared
                                                                // with the responses that carry them, not copied)
  uint64_t frames_received_ = 0;
  std::optional<uint64_t> wanted_from_;  // a cursor handed out and not yet redeemed: frames are kept
  std::vector<idl::SslField> fields_;
  std::vector<idl::Clock> clocks_;
  std::vector<idl::WorldState> worlds_;
  std::vector<idl::SslRobotFeedback> feedback_;
  std::vector<idl::CameraFrame> camera_inbox_;

  std::unique_ptr<dds::Participant> own_;
  dds::Bus& bus_;
  std::unique_ptr<dds::Writer<idl::SslRobotCommandPubSubType>> command_writers_[2];
  dds::ControlClient control_;
  std::unique_ptr<dds::Reader<idl::SslRobotFeedbackPubSubType>> feedback_readers_[2];
  std::unique_ptr<dds::Reader<idl::SslFieldPubSubType>> field_reader_;
  std::unique_ptr<dds::Reader<idl::ClockPubSubType>> clock_reader_;
  std::unique_ptr<dds::Reader<idl::WorldStatePubSubType>> world_reader_;
  std::unique_ptr<dds::Reader<idl::CameraFramePubSubType>> camera_reader_;
};

SimLink::SimLink(const dds::ParticipantOptions& options) {
  auto own = std::make_unique<dds::Participant>(options);
  dds::Bus& bus = *own;
  impl_ = std::make_unique<Impl>(std::move(own), bus, options.name);
}
SimLink::SimLink(dds::Bus& bus, const std::string& name) : impl_(std::make_unique<Impl>(nullptr, bus, name)) {}
SimLink::~SimLink() = default;
std::string SimLink::TopicName(dds::Topic topic) const { return impl_->bus().TopicName(topic); }
std::string SimLink::DescribeBus() const { return impl_->bus().Describe(); }
SimLink::View SimLink::Now() { return impl_->Now(); }
void SimLink::Command(const idl::SslRobotCommand& command) { impl_->Command(command); }
std::vector<dds::ControlOutcome> SimLink::Control(std::vector<idl::SimControl> requests,
                                                  std::chrono::milliseconds timeout,
                                                  const dds::ControlClient::StopFn& stop) {
  return impl_->Control(std::move(requests), timeout, stop);
}
uint64_t SimLink::FrameCursor() { return impl_->FrameCursor(); }
std::vector<std::shared_ptr<const idl::CameraFrame>> SimLink::FramesSince(uint64_t cursor) {
  return impl_->FramesSince(cursor);
}
uint64_t SimLink::Overflowed() const { return impl_->Overflowed(); }
dds::Authentications SimLink::AuthenticationsNow() const { return impl_->AuthenticationsNow(); }

}  // namespace turf
