#include "participants/replay/replay.h"

#include <fastdds/rtps/common/SerializedPayload.h>
#include <spdlog/spdlog.h>
#include <turf/idl/ClockPubSubTypes.h>
#include <turf/idl/JointsPubSubTypes.h>
#include <turf/idl/SensorStatsPubSubTypes.h>
#include <turf/idl/SimControlPubSubTypes.h>
#include <turf/idl/SimRecordPubSubTypes.h>
#include <turf/idl/SslRobotPubSubTypes.h>
#include <turf/idl/SslVisionPubSubTypes.h>
#include <turf/idl/WorldStatePubSubTypes.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <map>
#include <memory>
#include <stdexcept>
#include <string_view>
#include <thread>
#include <tuple>
#include <vector>

#include "codecs/mcap/reader.h"
#include "dds/participant.h"
#include "participants/common/mcap_file.h"
#include "participants/replay/replay_clock.h"

namespace turf {
namespace {

using SteadyClock = std::chrono::steady_clock;

constexpr size_t kMaxSample = 64u << 20;  // no turf sample comes near this

// One published topic: its writer and the CDR deserializer of its type.
class Player {
 public:
  explicit Player(dds::Topic topic) : topic_(topic) {}
  virtual ~Player() = default;
  // False if the bytes are no CDR sample of the type.
  virtual bool Publish(std::string_view cdr) = 0;
  virtual int Matched() const = 0;
  dds::Topic topic() const { return topic_; }
  const dds::TopicInfo& info() const { return topic_.info(); }

 private:
  dds::Topic topic_;
};

template <class PubSub>
class TypedPlayer final : public Player {
 public:
  TypedPlayer(dds::Bus& bus, const dds::TopicDef<PubSub>& topic) : Player(topic), writer_(bus.MakeWriter(topic)) {}
  bool Publish(std::string_view cdr) override {
    if (cdr.size() > kMaxSample) return false;
    eprosima::fastrtps::rtps::SerializedPayload_t payload(static_cast<uint32_t>(cdr.size()));
    std::memcpy(payload.data, cdr.data(), cdr.size());
    payload.length = static_cast<uint32_t>(cdr.size());
    if (!type_.deserialize(&payload, &sample_)) return false;
    writer_->Write(sample_);
    return true;
  }
  int Matched() const override { return writer_->Matched(); }

 private:
  std::unique_ptr<dds::Writer<PubSub>> writer_;
  PubSub type_;
  dds::SampleOf<PubSub> sample_;
};

struct Stopped {};

class Replayer {
 public:
  Replayer(const ReplayOptions& o, const std::function<bool()>& stop)
      : options_(o), stop_(stop), participant_(DdsOptions(o)) {
    std::apply([this](const auto&... topic) { (Add(topic), ...); }, dds::kTypedTopics);
    participant_.LogTopics();
  }

  ReplayTotals Run() {
    McapFileSource source(options_.file);
    if (!source.ok()) throw std::invalid_argument("cannot read " + options_.file + ": " + source.error());
    if (options_.wait_for_reader) WaitForReader();
    clock_ = std::make_unique<ReplayClock>(options_.speed, SteadyClock::now());
    last_progress_ = SteadyClock::now();
    mcap::FileInfo info;
    mcap::Damage damage;
    try {
      damage = mcap::Scan(source, {}, &info, [&](const mcap::Channel& c, const mcap::Message& m) { Play(info, c, m); });
    } catch (const Stopped&) {
      spdlog::info("{} at {} messages", totals_.reached_end ? "reached --end" : "stopped", totals_.published);
      if (!totals_.reached_end) return totals_;
    }
    if (damage.error == mcap::ReadError::kBadMagic || damage.error == mcap::ReadError::kNewerVersion)
      throw std::invalid_argument(options_.file + ": " + damage.Describe());
    if (!damage.ok()) spdlog::warn("{}: played up to the damage: {}", options_.file, damage.Describe());
    // The writers stay a moment so reliable readers get the last samples (the Bus has no wait for
    // acknowledgements).
    const auto linger_end = SteadyClock::now() + std::chrono::milliseconds(500);
    while (SteadyClock::now() < linger_end && !stop_()) std::this_thread::sleep_for(std::chrono::milliseconds(20));
    spdlog::info("replayed {} messages ({} inputs or unknown channels skipped, {} refused, {} before --start)",
                 totals_.published, totals_.skipped, totals_.refused, totals_.before_start);
    return totals_;
  }

 private:
  template <class PubSub>
  void Add(const dds::TopicDef<PubSub>& topic) {
    if (topic.info().direction == dds::Direction::kSubscribed) return;  // inputs are never replayed
    players_.push_back(std::make_unique<TypedPlayer<PubSub>>(participant_, topic));
  }

  void WaitForReader() {
    const auto deadline = SteadyClock::now() + std::chrono::seconds(30);
    spdlog::info("waiting for a reader of a replayed topic (up to 30 s)");
    while (SteadyClock::now() < deadline) {
      if (stop_()) throw Stopped{};
      for (const auto& p : players_)
        if (p->Matched() > 0) return;
      std::this_thread::sleep_for(std::chrono::milliseconds(20));  // discovery has no event here
    }
    spdlog::warn("no reader matched within 30 s; replaying anyway");
  }

  // The player of a recorded channel: the table topic its name ends with whose DDS type its schema names.
  Player* Resolve(const mcap::FileInfo& info, const mcap::Channel& c) {
    const auto known = players_of_channel_.find(c.id);
    if (known != players_of_channel_.end()) return known->second;
    Player* found = nullptr;
    const auto schema = info.schemas.find(c.schema_id);
    for (const auto& p : players_) {
      const std::string suffix = std::string("/") + p->info().suffix;
      const bool named =
          c.topic.size() > suffix.size() && c.topic.compare(c.topic.size() - suffix.size(), suffix.size(), suffix) == 0;
      if (named && schema != info.schemas.end() && schema->second.name == p->info().dds_type &&
          c.message_encoding == "cdr")
        found = p.get();
    }
    spdlog::info("channel {} ({}): {}", c.id, c.topic,
                 found ? "replayed as " + participant_.TopicName(found->topic())
                       : std::string("not replayed (an input or no table topic of that type)"));
    players_of_channel_[c.id] = found;
    return found;
  }

  void Play(const mcap::FileInfo& info, const mcap::Channel& c, const mcap::Message& m) {
    Player* player = Resolve(info, c);
    if (player == nullptr) {
      ++totals_.skipped;
      return;
    }

    if (!have_first_) {
      have_first_ = true;
      start_ns_ = m.log_time + static_cast<uint64_t>(options_.start_s * 1e9);
      end_ns_ = options_.end_s > 0 ? m.log_time + static_cast<uint64_t>(options_.end_s * 1e9) : UINT64_MAX;
      clock_->SetOrigin(start_ns_);
    }
    if (m.log_time > end_ns_) {
      totals_.reached_end = true;
      throw Stopped{};
    }
    if (m.log_time < start_ns_ && player->info().direction != dds::Direction::kLatched) {
      ++totals_.before_start;
      return;
    }
    WaitWhilePaused();
    for (auto due = clock_->Due(m.log_time); SteadyClock::now() < due; due = clock_->Due(m.log_time)) {
      // Real-time pacing: sleep, in slices that notice a stop or a pause.
      if (stop_()) throw Stopped{};
      std::this_thread::sleep_for(
          std::min<SteadyClock::duration>(due - SteadyClock::now(), std::chrono::milliseconds(50)));
      WaitWhilePaused();
    }
    if (stop_()) throw Stopped{};
    last_sim_time_ns_ = m.publish_time;
    if (player->Publish(m.data)) {
      ++totals_.published;
    } else if (++totals_.refused <= 10) {
      spdlog::warn("refused a message of {} (sequence {}): no CDR sample of {}", c.topic, m.sequence,
                   player->info().dds_type);
    }
    if (SteadyClock::now() - last_progress_ >= std::chrono::duration<double>(options_.progress_interval_s)) {
      spdlog::info("replaying: {} messages, sim time {:.3f} s", totals_.published,
                   static_cast<double>(m.publish_time) * 1e-9);
      last_progress_ = SteadyClock::now();
    }
  }

  // While options_.paused() answers true: the pacing clock stands still (checked every 50 ms).
  void WaitWhilePaused() {
    if (!options_.paused || !options_.paused()) return;
    clock_->Pause(SteadyClock::now());
    spdlog::info("paused (sim time {:.3f} s); SIGUSR1 resumes", last_sim_time_ns_ * 1e-9);
    while (options_.paused()) {
      if (stop_()) throw Stopped{};
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    clock_->Resume(SteadyClock::now());
    spdlog::info("resumed");
  }

  const ReplayOptions& options_;
  const std::function<bool()>& stop_;
  dds::Participant participant_;
  std::vector<std::unique_ptr<Player>> players_;  // after the participant: deleted first
  std::map<uint16_t, Player*> players_of_channel_;
  std::unique_ptr<ReplayClock> clock_;
  SteadyClock::time_point last_progress_;
  bool have_first_ = false;
  uint64_t start_ns_ = 0;
  uint64_t end_ns_ = UINT64_MAX;
  uint64_t last_sim_time_ns_ = 0;
  ReplayTotals totals_;
};

}  // namespace

ReplayTotals Replay(const ReplayOptions& options, const std::function<bool()>& stop) {
  Replayer replayer(options, stop);
  return replayer.Run();
}

}  // namespace turf
