#include "participants/viewer/recording_viewer.h"

#include <spdlog/spdlog.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <stdexcept>
#include <thread>
#include <utility>

#include "participants/common/mcap_file.h"
#include "participants/common/process.h"
#include "participants/viewer/http_rules.h"
#include "participants/viewer/recording.h"
#include "participants/viewer/viewer_json.h"
#include "participants/viewer/web_server.h"

namespace turf {

namespace {

using SteadyClock = std::chrono::steady_clock;

std::unique_ptr<viewer::Recording> Load(const std::string& path) {
  auto source = std::make_unique<McapFileSource>(path);
  if (!source->ok()) throw std::invalid_argument("--recording: cannot read " + path + ": " + source->error());
  auto recording = std::make_unique<viewer::Recording>(std::move(source));
  if (recording->refused()) throw std::invalid_argument("--recording: " + path + ": " + recording->damage().Describe());
  return recording;
}

}  // namespace

class RecordingViewer::Impl {
 public:
  explicit Impl(const ViewerOptions& options) : options_(options) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(std::filesystem::path(options_.web_root) / "index.html", ec))
      throw std::invalid_argument("--web-root: no index.html in '" + options_.web_root + "'");
    const auto started = SteadyClock::now();
    recording_ = Load(options_.recording);
    load_seconds_ = std::chrono::duration<double>(SteadyClock::now() - started).count();
    if (!recording_->damage().ok())
      spdlog::warn("{}: read up to the damage, the rest is not shown: {}", options_.recording,
                   recording_->damage().Describe());
    viewer::WebServerOptions web;
    web.listen = options_.listen;
    web.host_names = viewer::PageHostNames(options_.allow_hosts);
    web.port = options_.port;
    web.web_root = options_.web_root;
    web.hello = viewer::HelloJson(options_.prefix);
    viewer::WebServerHandlers handlers;
    // Pages cannot change a recording: every message is answered with a refusal.
    handlers.on_message = [this](uint64_t client, const std::string&) {
      ++refused_;
      if (!ready_.load()) return;  // server_ is being set
      server_->SendTo(client, viewer::RefusedJson("recording", "this is a recording: it cannot be changed"));
    };
    handlers.on_refused = [this](uint64_t, const std::string& kind, const std::string& detail) {
      ++refused_;
      rejects_.Reject(kind, detail);
    };
    handlers.on_get = [this](std::string_view target) { return Answer(target); };
    std::string error;
    server_ = viewer::WebServer::Start(std::move(web), std::move(handlers), &error);
    if (!server_) {
      if (error.rfind("--listen", 0) == 0) throw std::invalid_argument(error);
      throw std::runtime_error(error);
    }
    ready_.store(true);
    const std::string field = recording_->FieldJson();
    if (!field.empty()) server_->Publish(viewer::Channel::kField, field);
  }

  void Run(const std::function<bool()>& stop) {
    ReportStartup();
    auto next_status = SteadyClock::now() + std::chrono::seconds(10);
    while (!stop()) {
      std::this_thread::sleep_for(std::chrono::milliseconds(50));  // nothing to do but notice a stop
      if (SteadyClock::now() >= next_status) {
        ReportStatus();
        next_status += std::chrono::seconds(10);
      }
    }
    ReportStatus();
  }

  uint16_t port() const { return server_->port(); }
  std::string Url() const { return server_->Url(); }
  uint64_t requests() const { return requests_.load(); }

 private:
  // On the server's I/O thread; the recording is read-only by now.
  std::optional<std::string> Answer(std::string_view target) {
    const std::string_view path = target.substr(0, target.find('?'));
    std::string body;
    if (path == "/recording/info") {
      body = recording_->InfoJson(std::filesystem::path(options_.recording).filename().string());
    } else if (path == "/recording/state" || path == "/recording/stats") {
      const std::optional<int64_t> t = viewer::QueryTime(target);
      if (!t) {
        ++refused_;
        return std::nullopt;
      }
      body = path == "/recording/state" ? recording_->StateJsonAt(*t) : recording_->StatsJsonAt(*t);
    }
    if (body.empty()) return std::nullopt;
    ++requests_;
    return body;
  }

  void ReportStartup() const {
    using R = viewer::Recording;
    const auto span = recording_->Span();
    spdlog::info("open {} in a browser: recording {} with a time slider", server_->Url(), options_.recording);
    spdlog::info("serving the page from {}", options_.web_root);
    spdlog::info(
        "read in {:.2f} s: {} world states, {} clocks, {} camera frames, {} stats, {} robots/links, {} fields, "
        "{} legged scenes; {} other messages skipped",
        load_seconds_, recording_->count(R::kState), recording_->count(R::kClock), recording_->count(R::kCamera),
        recording_->count(R::kStats), recording_->count(R::kLinks), recording_->count(R::kField),
        recording_->count(R::kLegged), recording_->skipped());
    if (span) {
      spdlog::info("simulation time {:.3f} s to {:.3f} s", span->first * 1e-9, span->second * 1e-9);
    } else {
      spdlog::warn("{}: no world state or robots/links sample to show", options_.recording);
    }
  }

  void ReportStatus() const {
    spdlog::info("pages={} requests={} refused={}", server_->Stats().pages, requests_.load(), refused_.load());
  }

  ViewerOptions options_;
  std::unique_ptr<viewer::Recording> recording_;
  double load_seconds_ = 0;
  std::atomic<uint64_t> requests_{0};
  std::atomic<uint64_t> refused_{0};
  RejectLog rejects_{"page input"};  // HTTP and WebSocket refusals: logged rate-limited
  std::atomic<bool> ready_{false};
  // Last: the server's I/O thread calls into the members above, so it stops first.
  std::unique_ptr<viewer::WebServer> server_;
};

RecordingViewer::RecordingViewer(const ViewerOptions& options) : impl_(std::make_unique<Impl>(options)) {}
RecordingViewer::~RecordingViewer() = default;
void RecordingViewer::Run(const std::function<bool()>& stop) { impl_->Run(stop); }
uint16_t RecordingViewer::port() const { return impl_->port(); }
std::string RecordingViewer::Url() const { return impl_->Url(); }
uint64_t RecordingViewer::requests() const { return impl_->requests(); }

}  // namespace turf
