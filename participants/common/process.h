// What every turf process shares: log setup, clean shutdown on SIGINT/SIGTERM,
// and counted, rate-limited reports of refused input.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <map>
#include <mutex>
#include <string>
#include <string_view>

namespace turf {

// Configures the default spdlog logger ("[time] [name] [level] message").
// Returns false (and logs why) if `level` is not a spdlog level name.
bool SetupLogging(const std::string& process_name, const std::string& level);

// SIGINT and SIGTERM set a flag that StopRequested() reads. A second signal a second or more after the first
// exits at once (exit 130: an impatient Ctrl-C); one sooner is the same stop (`turf launch` and a service manager
// both sending SIGTERM to the process). Installing them also unblocks them, so a stop asked before (pending while
// blocked) is heard. ParticipantMain installs them when it is made, the first thing of every participant's main().
inline constexpr int64_t kSameStopNs = 1'000'000'000;
void InstallStopSignals();
bool StopRequested();
void RequestStop();

// Asks the process to stop and then start again as it was started (ParticipantMain::Run runs the same program with
// the same arguments once the body has returned): a DDS participant made anew, for what only that mends (Fast DDS
// 2.9.1's stalled handshakes, participants/common/stalled_authentication.h). A SIGINT or SIGTERM cancels it.
void RequestRestart();
bool RestartRequested();

// `text` cut to `max` bytes, with how long it was after it ("abc... (4000000 bytes)"): names a peer chose, in log
// lines and in replies.
std::string Clipped(std::string_view text, size_t max = 64);

// `text` with its control bytes (below 0x20, and 0x7f) written as \xNN: what a peer sent, safe to log (no forged
// line, no terminal escape).
std::string Printable(std::string_view text);

// Counts refused inputs per kind and logs them (the detail through Printable): the first of each kind at
// once, then at most one summary line per kind every `interval`. Thread-safe:
// a participant's threads share one. With LogLine::kEvent the same counting
// and limit serve events that anyone can cause in bulk (clients connecting and
// leaving): information lines "<what> (<kind>): <detail>" instead of warnings
// "refused <what> (<kind>): <detail>".
enum class LogLine { kRefusal, kEvent };
class RejectLog {
 public:
  static constexpr size_t kMaxDetail = 512;  // bytes of a detail logged (Clipped)
  explicit RejectLog(std::string what, std::chrono::seconds interval = std::chrono::seconds(5),
                     LogLine line = LogLine::kRefusal);
  void Reject(const std::string& kind, const std::string& detail);
  uint64_t Count(const std::string& kind) const;
  uint64_t Total() const { return total_.load(); }
  std::map<std::string, uint64_t> counts() const;

 private:
  const std::string what_;
  const std::chrono::seconds interval_;
  const LogLine line_;
  std::atomic<uint64_t> total_{0};
  mutable std::mutex mutex_;
  std::map<std::string, uint64_t> counts_;
  std::map<std::string, uint64_t> reported_;
  std::map<std::string, std::chrono::steady_clock::time_point> last_log_;
};

}  // namespace turf
