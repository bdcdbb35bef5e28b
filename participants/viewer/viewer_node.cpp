#include "participants/viewer/viewer_node.h"

#include <spdlog/spdlog.h>
#include <turf/idl/ClockPubSubTypes.h>
#include <turf/idl/JointsPubSubTypes.h>
#include <turf/idl/SensorStatsPubSubTypes.h>
#include <turf/idl/SimControlPubSubTypes.h>
#include <turf/idl/SslVisionPubSubTypes.h>
#include <turf/idl/WorldStatePubSubTypes.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <deque>
#include <filesystem>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <utility>

#include "dds/control_client.h"
#include "dds/participant.h"
#include "participants/common/overflow_watch.h"
#include "participants/common/process.h"
#include "participants/common/stalled_authentication.h"
#include "participants/common/wakeup.h"
#include "participants/viewer/camera_frames.h"
#include "participants/viewer/http_rules.h"
#include "participants/viewer/viewer_json.h"
#include "participants/viewer/viewer_model.h"
#include "participants/viewer/web_server.h"

namespace turf {

namespace {

using SteadyClock = std::chrono::steady_clock;
constexpr size_t kMaxInbox = 1024;  // page messages waiting for the loop
constexpr auto kControlSettle = std::chrono::milliseconds(100);
constexpr auto kReplyTimeout = std::chrono::seconds(10);  // then the page is told nobody answered

// Wall clock, for what the page shows a person ("gone since 18:52:07"), never for the simulation.
int64_t UnixNowMs() {
  return std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::system_clock::now().time_since_epoch())
      .count();
}

void CheckOptions(const ViewerOptions& o) {
  if (!(std::isfinite(o.rate_hz) && o.rate_hz >= 1.0 && o.rate_hz <= 1000.0))
    throw std::invalid_argument("--rate must be in [1, 1000] Hz");
  std::error_code ec;
  if (!std::filesystem::is_regular_file(std::filesystem::path(o.web_root) / "index.html", ec))
    throw std::invalid_argument("--web-root: no index.html in '" + o.web_root + "'");
}

}  // namespace

class ViewerNode::Impl {
 public:
  explicit Impl(ViewerOptions options)
      : options_((CheckOptions(options), std::move(options))),
        client_(fmt::format("{}-{}", options_.name, getpid())),
        model_(client_, options_.prefix),
        participant_(DdsOptions(options_)),
        state_reader_(Reader(dds::Topic::kWorldState)),
        clock_reader_(Reader(dds::Topic::kClock)),
        field_reader_(Reader(dds::Topic::kSslField)),
        camera_reader_(Reader(dds::Topic::kSslCamera)),
        stats_reader_(Reader(dds::Topic::kStats)),
        legged_reader_(Reader(dds::Topic::kLeggedScene)),
        links_reader_(Reader(dds::Topic::kRobotLinks)),
        control_(participant_, client_, [this] { wakeup_.Notify(); }),
        rejects_("input") {
    viewer::WebServerOptions web;
    web.listen = options_.listen;
    web.host_names = viewer::PageHostNames(options_.allow_hosts);
    web.port = options_.port;
    web.web_root = options_.web_root;
    web.hello = model_.Hello();
    viewer::WebServerHandlers handlers;
    handlers.on_message = [this](uint64_t client, std::string text) { OnPageMessage(client, std::move(text)); };
    handlers.on_refused = [this](uint64_t client, const std::string& kind, const std::string& detail) {
      Reject(kind, detail);
      if (client != 0) OnPageMessage(client, viewer::RefusedJson(kind, detail), /*refusal=*/true);
    };
    handlers.on_image = [this](std::string_view target) { return camera_frames_.Jpeg(target); };
    std::string error;
    server_ = viewer::WebServer::Start(std::move(web), std::move(handlers), &error);
    if (!server_) {
      if (error.rfind("--listen", 0) == 0) throw std::invalid_argument(error);
      throw std::runtime_error(error);
    }
  }

  void Run(const std::function<bool()>& stop) {
    ReportStartup();
    const auto period =
        std::chrono::duration_cast<SteadyClock::duration>(std::chrono::duration<double>(1.0 / options_.rate_hz));
    auto next_push = SteadyClock::now();
    auto next_status = SteadyClock::now() + std::chrono::seconds(10);
    while (!stop()) {
      // Wake for new samples, a due state push, or at least every 50 ms.
      const auto idle = SteadyClock::now() + std::chrono::milliseconds(50);
      wakeup_.WaitUntil(dirty_ ? std::min(idle, next_push) : idle);
      HandleField();
      HandleLegged();
      HandleStats();
      HandleCameras();
      HandleStates();
      control_.Dispatch();  // replies go to the page that asked (OnReply)
      UpdateControlMatched();
      HandlePages();
      HandleOverflow();
      if (restart_.Check(participant_.AuthenticationsNow(), !receiving_)) break;
      const auto after = SteadyClock::now();
      if (dirty_ && after >= next_push && model_.has_state()) {
        server_->Publish(viewer::Channel::kState, model_.State());
        ++states_pushed_;
        dirty_ = false;
        // On the rate's grid while states keep coming; after a lull, not two pushes at once.
        next_push = std::max(next_push + period, after + period / 2);
      }
      if (after >= next_status) {
        ReportStatus();
        next_status = after + std::chrono::seconds(10);
      }
    }
    ReportStatus();
  }

  uint16_t port() const { return server_->port(); }
  std::string Url() const { return server_->Url(); }
  ViewerStats Stats() const {
    const viewer::WebServerStats web = server_->Stats();
    return {web.pages,
            control_matched_.load(),
            states_received_.load(),
            states_pushed_.load(),
            controls_sent_.load(),
            replies_.load(),
            rejects_.Total() + camera_frames_.refused(),
            web.frames_dropped};
  }
  uint64_t Rejected(const std::string& kind) const { return rejects_.Count(kind); }

 private:
  template <class PubSub>
  std::unique_ptr<dds::Reader<PubSub>> Reader(const dds::TopicDef<PubSub>& topic) {
    return participant_.MakeReader<PubSub>(topic, [this] { wakeup_.Notify(); });
  }

  void Reject(const std::string& kind, const std::string& detail) { rejects_.Reject(kind, detail); }
  // A DDS sample the model refused.
  bool Refused(const char* topic, viewer::SampleError e) {
    if (e == viewer::SampleError::kOk) return false;
    Reject(fmt::format("{}.{}", topic, viewer::SampleErrorName(e)), "sample dropped; keeping the last good one");
    return true;
  }

  // On the server's I/O thread: hand a page's message (or the answer to a
  // message the server refused) to the loop.
  void OnPageMessage(uint64_t client, std::string text, bool refusal = false) {
    {
      std::lock_guard<std::mutex> lock(inbox_mutex_);
      if (inbox_.size() >= kMaxInbox) {
        inbox_overflow_ = true;
      } else {
        inbox_.push_back({client, std::move(text), refusal});
      }
    }
    wakeup_.Notify();
  }

  // A request written before turf-sim has matched our control writer would be
  // lost (the topic is volatile), and so would its reply before it has matched
  // our reply reader. Our side's matches come first; world states arriving
  // show turf-sim has taken in our endpoints too, and a short settling time
  // covers the rest. Until then page actions are refused (page.no_simulator).
  void UpdateControlMatched() {
    const bool matched = control_.ServerMatched() && model_.has_state();
    const auto now = SteadyClock::now();
    if (!matched) matched_since_.reset();
    if (matched && !matched_since_) matched_since_ = now;
    const bool live = matched_since_ && now - *matched_since_ >= kControlSettle;
    if (live != control_matched_.load()) {
      spdlog::info(live ? "turf-sim reads our control requests: page controls are live"
                        : "no turf-sim control reader: page controls are refused until one is there");
      dirty_ = true;
      // Gone after having been there: the page marks what it shows as turf-sim's last word, with the time.
      model_.SetSimGoneSince(live ? 0 : UnixNowMs());
    }
    control_matched_.store(live);
    model_.SetControlMatched(live);
  }

  void HandlePages() {
    std::deque<Inbound> messages;
    bool overflow = false;
    {
      std::lock_guard<std::mutex> lock(inbox_mutex_);
      messages.swap(inbox_);
      overflow = std::exchange(inbox_overflow_, false);
    }
    if (overflow) Reject("page.backlog", "page messages arrived faster than the loop could take them");
    for (const auto& [client, text, refusal] : messages) {
      if (refusal) {
        model_.CountRefusedPage();
        server_->SendTo(client, text);
        continue;
      }
      const viewer::PageRequest r = model_.OnPageMessage(text);
      if (r.error != viewer::PageError::kOk) {
        const std::string kind = fmt::format("page.{}", viewer::PageErrorName(r.error));
        Reject(kind, r.detail);
        server_->SendTo(client, viewer::RefusedJson(viewer::PageErrorName(r.error), r.detail));
        continue;
      }
      if (!control_matched_.load()) {
        const std::string why = "turf-sim is not there (no control reader on " +
                                participant_.TopicName(dds::Topic::kControl) + "): nothing was sent";
        model_.CountRefusedPage();
        Reject("page.no_simulator", why);
        server_->SendTo(client, viewer::RefusedJson("no_simulator", why));
        continue;
      }
      const uint64_t id = control_.Send(r.control, kReplyTimeout,
                                        [this, page = client](const dds::ControlOutcome& o) { OnReply(page, o); });
      spdlog::debug("page {}: {} -> control request {}", client, r.op, id);
      ++controls_sent_;
    }
  }

  void HandleField() {
    if (!field_reader_->Take(&field_inbox_)) return;
    for (const idl::SslField& f : field_inbox_) {
      if (Refused("field", model_.OnField(f))) continue;
      if (!field_logged_) {
        spdlog::info("field known: division {}, {} x {} m, {} robots a team", f.division() == 2 ? "B" : "A",
                     f.field_length(), f.field_width(), f.robots_per_team());
        field_logged_ = true;
      }
      server_->Publish(viewer::Channel::kField, model_.Field());
    }
  }

  // Legged scenes: the robots' shapes (latched, like the field) and their body poses.
  void HandleLegged() {
    if (legged_reader_->Take(&legged_inbox_)) {
      for (const idl::LeggedSceneInfo& s : legged_inbox_) {
        if (Refused("legged_scene", model_.OnLeggedScene(s))) continue;
        spdlog::info("legged scene '{}' known: {} robots, {}", s.name(), s.robots().size(),
                     s.has_field() ? fmt::format("field {} x {} m", s.field_length(), s.field_width()) : "no field");
        server_->Publish(viewer::Channel::kField, model_.Field());
        dirty_ = true;
      }
    }
    if (!links_reader_->Take(&links_inbox_)) return;
    for (const idl::LinkState& l : links_inbox_) dirty_ |= !Refused("links", model_.OnLinks(l));
  }

  void HandleStats() {
    if (!stats_reader_->Take(&stats_inbox_)) return;
    for (const idl::SensorStats& s : stats_inbox_)
      if (!Refused("stats", model_.OnStats(s))) server_->Publish(viewer::Channel::kStats, model_.Stats());
  }

  void HandleCameras() {
    if (!camera_reader_->Take(&camera_inbox_)) return;
    for (const idl::CameraFrame& f : camera_inbox_) dirty_ |= !Refused("camera", model_.OnCamera(f));
  }

  void HandleStates() {
    if (clock_reader_->Take(&clock_inbox_))
      for (const idl::Clock& c : clock_inbox_) dirty_ |= !Refused("clock", model_.OnClock(c));
    if (!state_reader_->Take(&state_inbox_)) return;
    states_received_ += state_inbox_.size();
    // Only the newest good state is shown.
    for (auto it = state_inbox_.rbegin(); it != state_inbox_.rend(); ++it) {
      if (Refused("world_state", model_.OnWorldState(*it))) continue;
      dirty_ = true;
      break;
    }
    if (!receiving_) {
      spdlog::info("receiving world states");
      receiving_ = true;
    }
  }

  // Only the page that asked sees the answer; the others see its effect in the state.
  void OnReply(uint64_t page, const dds::ControlOutcome& o) {
    if (!o.reply) {
      const std::string why = o.Describe();
      Reject(fmt::format("control.{}", dds::ControlCallErrorName(o.error)), why);
      server_->SendTo(page, viewer::RefusedJson(dds::ControlCallErrorName(o.error), why));
      return;
    }
    ++replies_;
    const idl::SimControlReply& r = *o.reply;
    if (r.result() != idl::RESULT_OK)
      spdlog::info("turf-sim refused page {}'s {}: {}", page, viewer::OpName(r.op()), r.reason());
    server_->SendTo(page, viewer::ReplyJson(r));
  }

  void HandleOverflow() {
    const uint64_t overflow = state_reader_->Overflowed() + clock_reader_->Overflowed() + field_reader_->Overflowed() +
                              camera_reader_->Overflowed() + stats_reader_->Overflowed() + control_.Overflowed() +
                              legged_reader_->Overflowed() + links_reader_->Overflowed();
    overflow_.Check(overflow, [this](const char* kind, const std::string& detail) { Reject(kind, detail); });
  }

  void ReportStartup() const {
    auto name = [this](dds::Topic t) { return participant_.TopicName(t); };
    const bool everywhere = options_.listen == "0.0.0.0" || options_.listen == "::";
    const bool local = options_.listen == "127.0.0.1" || options_.listen == "::1";
    spdlog::info("open {} in a browser (WebSocket at /ws){}", server_->Url(),
                 local        ? ", this machine only (--listen to expose)"
                 : everywhere ? ": every interface, so use this machine's name or address"
                              : "");
    spdlog::info("serving the page from {}", options_.web_root);
    spdlog::info("{}", participant_.Describe());
    spdlog::info("subscribing {}, {}, {} (latched), {}, {}, {}; legged scenes: {} (latched), {}",
                 name(dds::Topic::kWorldState), name(dds::Topic::kClock), name(dds::Topic::kSslField),
                 name(dds::Topic::kSslCamera), name(dds::Topic::kStats), name(dds::Topic::kControlReply),
                 name(dds::Topic::kLeggedScene), name(dds::Topic::kRobotLinks));
    spdlog::info("publishing {} as client '{}'; state to the pages at up to {:.0f} Hz", name(dds::Topic::kControl),
                 client_, options_.rate_hz);
    spdlog::info("waiting for turf-sim on domain {} prefix '{}'", options_.domain, options_.prefix);
  }

  void ReportStatus() const {
    const ViewerStats s = Stats();
    spdlog::info("pages={} states in={} out={} skipped={} controls={} replies={} refused={}", s.pages,
                 s.states_received, s.states_pushed, s.frames_dropped, s.controls_sent, s.replies, s.refused);
  }

  ViewerOptions options_;
  std::string client_;
  viewer::ViewerModel model_;  // loop thread only
  Wakeup wakeup_;
  dds::Participant participant_;
  dds::ReaderOf<dds::Topic::kWorldState> state_reader_;
  dds::ReaderOf<dds::Topic::kClock> clock_reader_;
  dds::ReaderOf<dds::Topic::kSslField> field_reader_;
  dds::ReaderOf<dds::Topic::kSslCamera> camera_reader_;
  dds::ReaderOf<dds::Topic::kStats> stats_reader_;
  dds::ReaderOf<dds::Topic::kLeggedScene> legged_reader_;
  dds::ReaderOf<dds::Topic::kRobotLinks> links_reader_;
  dds::ControlClient control_;

  std::vector<idl::WorldState> state_inbox_;
  std::vector<idl::Clock> clock_inbox_;
  std::vector<idl::SslField> field_inbox_;
  std::vector<idl::CameraFrame> camera_inbox_;
  std::vector<idl::SensorStats> stats_inbox_;
  std::vector<idl::LeggedSceneInfo> legged_inbox_;
  std::vector<idl::LinkState> links_inbox_;
  bool dirty_ = false;
  bool receiving_ = false;
  StalledAuthenticationRestart restart_;
  bool field_logged_ = false;
  OverflowWatch overflow_;

  std::mutex inbox_mutex_;
  struct Inbound {
    uint64_t client;
    std::string text;
    bool refusal;  // `text` is our answer to a message the server refused
  };
  std::deque<Inbound> inbox_;
  bool inbox_overflow_ = false;

  RejectLog rejects_;
  std::atomic<uint64_t> states_received_{0};
  std::atomic<uint64_t> states_pushed_{0};
  std::atomic<uint64_t> controls_sent_{0};
  std::atomic<uint64_t> replies_{0};
  std::atomic<bool> control_matched_{false};
  std::optional<SteadyClock::time_point> matched_since_;
  viewer::CameraFrames camera_frames_{
      viewer::CameraFramesOptions{options_.domain, options_.prefix, options_.security, options_.name}};

  // Last: the server's I/O thread calls into the members above, so it stops first.
  std::unique_ptr<viewer::WebServer> server_;
};

ViewerNode::ViewerNode(ViewerOptions options) : impl_(std::make_unique<Impl>(std::move(options))) {}
ViewerNode::~ViewerNode() = default;
void ViewerNode::Run(const std::function<bool()>& stop) { impl_->Run(stop); }
uint16_t ViewerNode::port() const { return impl_->port(); }
std::string ViewerNode::Url() const { return impl_->Url(); }
ViewerStats ViewerNode::Stats() const { return impl_->Stats(); }
uint64_t ViewerNode::Rejected(const std::string& kind) const { return impl_->Rejected(kind); }

}  // namespace turf
