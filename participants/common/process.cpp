#include "participants/common/process.h"

#include <spdlog/spdlog.h>

#include <unistd.h>
#include <atomic>
#include <csignal>
#include <cstdlib>
#include <ctime>

namespace turf {

bool SetupLogging(const std::string& process_name, const std::string& level) {
  spdlog::set_pattern(fmt::format("[%H:%M:%S.%e] [{}] [%^%l%$] %v", process_name));
  const spdlog::level::level_enum parsed = spdlog::level::from_str(level);
  // from_str answers "off" for anything it does not know.
  if (parsed == spdlog::level::off && level != "off") {
    spdlog::error("unknown log level '{}' (trace, debug, info, warn, error, critical, off)", level);
    return false;
  }
  spdlog::set_level(parsed);
  return true;
}

namespace {
std::atomic<int> g_stop_signals{0};
std::atomic<int64_t> g_first_signal_ns{0};  // CLOCK_MONOTONIC of the first stop signal
// RequestStop's: not a signal, so that one Ctrl-C after it still stops cleanly (a second one leaves at once).
std::atomic<bool> g_stop_requested{false};
std::atomic<bool> g_restart{false};

// Async-signal-safe: clock_gettime, atomics and _exit only.
void OnStopSignal(int) {
  g_restart.store(false);  // a stop from outside wins over a restart
  timespec t{};
  clock_gettime(CLOCK_MONOTONIC, &t);
  const int64_t now = int64_t{t.tv_sec} * 1'000'000'000 + t.tv_nsec;
  int64_t unset = 0;
  g_first_signal_ns.compare_exchange_strong(unset, now);  // before the count: a second handler reads it set
  if (g_stop_signals.fetch_add(1) >= 1 && now - g_first_signal_ns.load() >= kSameStopNs) _exit(130);
}
}  // namespace

void InstallStopSignals() {
  struct sigaction action {};
  action.sa_handler = OnStopSignal;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
  // A process started with them blocked (a parent's mask is inherited across exec) would otherwise never hear a
  // stop; one already pending is delivered now, as a stop.
  sigset_t stops;
  sigemptyset(&stops);
  sigaddset(&stops, SIGINT);
  sigaddset(&stops, SIGTERM);
  pthread_sigmask(SIG_UNBLOCK, &stops, nullptr);
  // A log written to a pipe whose reader has gone (a launcher killed, a closed terminal) fails with EPIPE instead of
  // killing the process before it stops cleanly (every child of a SIGKILLed `turf launch` died of SIGPIPE).
  signal(SIGPIPE, SIG_IGN);
}

bool StopRequested() { return g_stop_signals.load() > 0 || g_stop_requested.load(); }
void RequestStop() { g_stop_requested.store(true); }

void RequestRestart() {
  g_restart.store(true);
  RequestStop();
}
bool RestartRequested() { return g_restart.load(); }

std::string Clipped(std::string_view text, size_t max) {
  if (text.size() <= max) return std::string(text);
  return fmt::format("{}... ({} bytes)", text.substr(0, max), text.size());
}

std::string Printable(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte < 0x20 || byte == 0x7f)
      out += fmt::format("\\x{:02x}", byte);
    else
      out += c;  // printable ASCII, and UTF-8's multi-byte sequences as they are
  }
  return out;
}

RejectLog::RejectLog(std::string what, std::chrono::seconds interval, LogLine line)
    : what_(std::move(what)), interval_(interval), line_(line) {}

void RejectLog::Reject(const std::string& kind, const std::string& detail) {
  std::lock_guard<std::mutex> lock(mutex_);
  total_.fetch_add(1);
  const uint64_t n = ++counts_[kind];
  const auto now = std::chrono::steady_clock::now();
  auto it = last_log_.find(kind);
  if (it != last_log_.end() && now - it->second < interval_) return;
  const uint64_t since = n - reported_[kind];
  const bool refusal = line_ == LogLine::kRefusal;
  const std::string text =
      fmt::format("{}{} ({}): {}", refusal ? "refused " : "", what_, kind, Printable(Clipped(detail, kMaxDetail)));
  const spdlog::level::level_enum level = refusal ? spdlog::level::warn : spdlog::level::info;
  if (since <= 1)
    spdlog::log(level, "{}", text);
  else
    spdlog::log(level, "{} [{} {} since last report, {} in all]", text, since, refusal ? "refused" : "times", n);
  reported_[kind] = n;
  last_log_[kind] = now;
}

uint64_t RejectLog::Count(const std::string& kind) const {
  std::lock_guard<std::mutex> lock(mutex_);
  auto it = counts_.find(kind);
  return it == counts_.end() ? 0 : it->second;
}

std::map<std::string, uint64_t> RejectLog::counts() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return counts_;
}

}  // namespace turf
