#include "participants/replay/replay.h"

#include <fastdds/rtps/common/SerializedPayload.h>
#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <turf/idl/ClockPubSubTypes.h>
#include <turf/idl/JointsPubSubTypes.h>
#include <turf/idl/SensorStatsPubSubTypes.h>
#include <turf/idl/SimControlPubSubTypes.h>
#include <turf/idl/SimRecordPubSubTypes.h>
#include <turf/idl/SslRobotPubSubTypes.h>
#include <turf/idl/SslVisionPubSubTypes.h>
#include <turf/idl/WorldStatePubSubTypes.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <stdexcept>
#include <string_view>
#include <thread>
#include <tuple>
#include <variant>
#include <vector>

#include "codecs/mcap/reader.h"
#include "dds/participant.h"
#include "participants/common/mcap_file.h"
#include "participants/replay/line_reader.h"
#include "participants/replay/replay_clock.h"
#include "participants/replay/replay_control.h"
#include "participants/replay/replay_keys.h"

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
struct Restart {};  // a seek back: scan the file again from its start

class Replayer {
 public:
  Replayer(const ReplayOptions& o, const std::function<bool()>& stop)
      : options_(o), stop_(stop), participant_(DdsOptions(o)), control_(participant_) {
    std::apply([this](const auto&... topic) { (Add(topic), ...); }, dds::kTypedTopics);
    spdlog::info("replaying {} onto DDS domain {}, prefix '{}'", o.file, o.domain, o.prefix);
    participant_.LogTopics();
    spdlog::info("control: pause, resume, time mode (speed) and seek on {}, replies on {}",
                 participant_.TopicName(dds::Topic::kControl), participant_.TopicName(dds::Topic::kControlReply));
  }

  ReplayTotals Run() {
    McapFileSource source(options_.file);
    if (!source.ok()) throw std::invalid_argument("cannot read " + options_.file + ": " + source.error());
    if (options_.stdin_commands) ReadTerminal();
    if (options_.wait_for_reader && !WaitForReader()) {
      spdlog::info("stopped while waiting for a reader");
      return totals_;
    }
    clock_ = std::make_unique<ReplayClock>(options_.speed, SteadyClock::now());
    last_progress_ = SteadyClock::now();
    mcap::Damage damage;
    try {
      damage = ScanFromStart(source);
    } catch (const Stopped&) {
      spdlog::info("{} at {} messages", totals_.reached_end ? "reached --end" : "stopped", totals_.published);
      if (!totals_.reached_end) return totals_;
    }
    if (damage.error == mcap::ReadError::kBadMagic || damage.error == mcap::ReadError::kNewerVersion)
      throw std::invalid_argument(options_.file + ": " + damage.Describe());
    if (!damage.ok()) spdlog::warn("{}: played up to the damage: {}", options_.file, damage.Describe());
    if (seek_) RefuseSeekPastTheEnd();
    // The writers stay a moment so reliable readers get the last samples (the Bus has no wait for
    // acknowledgements).
    const auto linger_end = SteadyClock::now() + std::chrono::milliseconds(500);
    while (SteadyClock::now() < linger_end && !stop_()) std::this_thread::sleep_for(std::chrono::milliseconds(20));
    spdlog::info(
        "replayed {} messages ({} inputs or unknown channels skipped, {} refused, {} before --start, {} seeks)",
        totals_.published, totals_.skipped, totals_.refused, totals_.before_start, totals_.seeks);
    return totals_;
  }

 private:
  // Scans the file, again from its start after each seek back.
  mcap::Damage ScanFromStart(McapFileSource& source) {
    for (;;) {
      mcap::FileInfo info;
      try {
        return mcap::Scan(source, {}, &info, [&](const mcap::Channel& c, const mcap::Message& m) { Play(info, c, m); });
      } catch (const Restart&) {
        players_of_channel_.clear();  // channel ids belong to the scan's FileInfo
      }
    }
  }

  // Commands typed on the standard input (replay_keys.h), carried out with the control requests.
  void ReadTerminal() {
    spdlog::info("commands on standard input: {}", kReplayKeysHelp);
    terminal_ = std::make_unique<LineReader>(STDIN_FILENO, kMaxReplayLine, [this](std::string_view line) {
      auto command = ParseReplayLine(line);
      if (auto* refusal = std::get_if<ReplayRefusal>(&command)) {
        spdlog::warn("{}", refusal->reason);
        return;
      }
      control_.Submit(std::get<ReplayCommand>(std::move(command)));
    });
  }

  template <class PubSub>
  void Add(const dds::TopicDef<PubSub>& topic) {
    if (topic.info().direction == dds::Direction::kSubscribed) return;  // inputs are never replayed
    // The recorded replies answered the recorded match's clients; this replay answers its own (replay_control.h).
    if (topic == dds::Topic::kControlReply) return;
    players_.push_back(std::make_unique<TypedPlayer<PubSub>>(participant_, topic));
  }

  // False when stopped meanwhile.
  bool WaitForReader() {
    const auto deadline = SteadyClock::now() + std::chrono::seconds(30);
    spdlog::info("waiting for a reader of a replayed topic (up to 30 s)");
    while (SteadyClock::now() < deadline) {
      if (stop_()) return false;
      for (const auto& p : players_)
        if (p->Matched() > 0) return true;
      std::this_thread::sleep_for(std::chrono::milliseconds(20));  // discovery has no event here
    }
    spdlog::warn("no reader matched within 30 s; replaying anyway");
    return true;
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
    if (!announced_.count(c.id))
      spdlog::info("channel {} ({}): {}", c.id, c.topic,
                   found ? "replayed as " + participant_.TopicName(found->topic())
                         : std::string("not replayed (an input or no table topic of that type)"));
    announced_.insert(c.id);
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
    if (!WaitUntilDue(*player, m)) return;
    last_sim_time_ns_ = m.publish_time;
    last_log_time_ns_ = m.log_time;
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

  // Waits until `m` is due, carrying out control requests meanwhile; false if `m` is skipped (before --start or
  // before a seek's target). Latched topics (the field) are never skipped, so a viewer has them.
  bool WaitUntilDue(const Player& player, const mcap::Message& m) {
    const bool latched = player.info().direction == dds::Direction::kLatched;
    for (;;) {
      if (stop_()) throw Stopped{};
      Poll();
      if (!latched && seek_ && static_cast<int64_t>(m.publish_time) < seek_->seek_time_ns) return false;
      if (!latched && !seek_ && m.log_time < start_ns_) {
        ++totals_.before_start;
        return false;
      }
      if (seek_ && !latched) ArriveAtSeek(m);
      if (paused_) {
        control_.WaitUntil(SteadyClock::now() + std::chrono::milliseconds(50));  // SIGUSR1 has no event
        continue;
      }
      const auto due = clock_->Due(m.log_time);
      if (SteadyClock::now() >= due) return true;
      // Real-time pacing: sleep until due, waking for a request, and at least every 50 ms for a stop.
      control_.WaitUntil(std::min(due, SteadyClock::now() + std::chrono::milliseconds(50)));
    }
  }

  // Carries out the control requests that arrived and a SIGUSR1 toggle.
  void Poll() {
    const bool signalled = options_.paused && options_.paused();
    if (signalled != signal_paused_) {
      signal_paused_ = signalled;
      SetPaused(!paused_, "SIGUSR1");
    }
    for (ReplayCommand& command : control_.Take(static_cast<int64_t>(last_sim_time_ns_))) Carry(command);
  }

  void Carry(ReplayCommand& command) {
    const std::string who = command.local ? "terminal" : "'" + command.request.client() + "'";
    switch (command.kind) {
      case ReplayCommand::Kind::kPause:
      case ReplayCommand::Kind::kResume:
        SetPaused(command.kind == ReplayCommand::Kind::kPause, who);
        break;
      case ReplayCommand::Kind::kSpeed:
        clock_->Rebase(last_log_time_ns_, command.speed, SteadyClock::now());
        spdlog::info("speed {} ({})", command.speed > 0 ? fmt::format("{}", command.speed) : "max", who);
        break;
      case ReplayCommand::Kind::kSeek:
        Seek(command);
        return;  // replied when the target is reached
    }
    control_.Reply(command, static_cast<int64_t>(last_sim_time_ns_));
  }

  void SetPaused(bool paused, const std::string& who) {
    if (paused == paused_) return;
    paused_ = paused;
    if (paused) clock_->Pause(SteadyClock::now());
    if (!paused) clock_->Resume(SteadyClock::now());
    spdlog::info("{} at sim time {:.3f} s ({})", paused ? "paused" : "resumed", last_sim_time_ns_ * 1e-9, who);
  }

  // Forward: skip ahead to the target; back: scan again from the file's start (throws Restart).
  void Seek(const ReplayCommand& command) {
    if (seek_)
      control_.Reply(*seek_, static_cast<int64_t>(last_sim_time_ns_),
                     {idl::CONTROL_CANCELLED, "replaced by a later seek"});
    seek_ = command;
    start_ns_ = 0;  // a seek replaces --start
    ++totals_.seeks;
    spdlog::info("seeking to sim time {:.3f} s ({})", command.seek_time_ns * 1e-9,
                 command.local ? "terminal" : "'" + command.request.client() + "'");
    if (command.seek_time_ns < static_cast<int64_t>(last_sim_time_ns_)) throw Restart{};
  }

  void ArriveAtSeek(const mcap::Message& m) {
    clock_->Rebase(m.log_time, clock_->speed(), SteadyClock::now());
    spdlog::info("at sim time {:.3f} s", m.publish_time * 1e-9);
    control_.Reply(*seek_, static_cast<int64_t>(m.publish_time));
    last_sim_time_ns_ = m.publish_time;
    seek_.reset();
  }

  void RefuseSeekPastTheEnd() {
    control_.Reply(
        *seek_, static_cast<int64_t>(last_sim_time_ns_),
        {idl::CONTROL_OUT_OF_RANGE, fmt::format("no output at or after sim time {:.3f} s: the recording ends before it",
                                                seek_->seek_time_ns * 1e-9)});
    seek_.reset();
  }

  const ReplayOptions& options_;
  const std::function<bool()>& stop_;
  dds::Participant participant_;
  ReplayControl control_;                         // after the participant: deleted first
  std::vector<std::unique_ptr<Player>> players_;  // after the participant: deleted first
  std::unique_ptr<LineReader> terminal_;          // after the control: deleted (joined) first
  std::map<uint16_t, Player*> players_of_channel_;
  std::set<uint16_t> announced_;
  std::unique_ptr<ReplayClock> clock_;
  SteadyClock::time_point last_progress_;
  bool have_first_ = false;
  bool paused_ = false;
  bool signal_paused_ = false;
  std::optional<ReplayCommand> seek_;
  uint64_t start_ns_ = 0;
  uint64_t end_ns_ = UINT64_MAX;
  uint64_t last_sim_time_ns_ = 0;
  uint64_t last_log_time_ns_ = 0;
  ReplayTotals totals_;
};

}  // namespace

ReplayTotals Replay(const ReplayOptions& options, const std::function<bool()>& stop) {
  Replayer replayer(options, stop);
  return replayer.Run();
}

}  // namespace turf
