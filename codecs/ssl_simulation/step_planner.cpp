#include "codecs/ssl_simulation/step_planner.h"

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <limits>

namespace turf::simproto {

namespace {

// Far above any sync request (kMaxSyncStep is 1 s), far below overflow.
constexpr int64_t kMaxNs = 1'000'000'000'000;  // 1000 s

int64_t FloorDiv(int64_t a, int64_t b) {  // b > 0
  const int64_t q = a / b;
  return (a % b != 0 && a < 0) ? q - 1 : q;
}

}  // namespace

int64_t ToNanoseconds(double seconds) { return std::llround(seconds * 1e9); }

int64_t FloatSecondsToNanoseconds(float seconds) {
  if (!std::isfinite(seconds)) return 0;
  // A team asks for the same sim_step request after request: the last answer is kept (per thread).
  thread_local float last_seconds = 0.0f;
  thread_local int64_t last_ns = 0;
  if (seconds == last_seconds && std::signbit(seconds) == std::signbit(last_seconds)) return last_ns;
  // The shortest decimal that gives the float back (the closest such, as %.<n>g with the fewest digits n would).
  char text[32];
  const std::to_chars_result r = std::to_chars(text, text + sizeof(text) - 1, seconds);
  *r.ptr = '\0';
  last_seconds = seconds;
  last_ns = ToNanoseconds(std::strtod(text, nullptr));
  return last_ns;
}

uint32_t StepPlanner::Plan(int64_t request_ns, int64_t step_ns) {
  if (request_ns <= 0 || request_ns > kMaxNs || step_ns <= 0 || step_ns > kMaxNs) return 0;
  if (step_ns != step_ns_) {
    step_ns_ = step_ns;
    carry_ns_ = 0;
  }
  const int64_t owed = carry_ns_ + request_ns;
  // The nearest whole number of steps to `owed` (halves round up), never negative.
  int64_t steps = FloorDiv(2 * owed + step_ns, 2 * step_ns);
  if (steps < 0) steps = 0;
  if (steps > std::numeric_limits<uint32_t>::max()) return 0;
  carry_ns_ = owed - steps * step_ns;
  return static_cast<uint32_t>(steps);
}

void StepPlanner::Rebase(int64_t request_ns, uint32_t steps_run) {
  if (step_ns_ <= 0 || request_ns <= 0 || request_ns > kMaxNs || steps_run > kMaxNs / step_ns_) return Reset();
  carry_ns_ = request_ns - static_cast<int64_t>(steps_run) * step_ns_;
}

void StepPlanner::Reset() {
  step_ns_ = 0;
  carry_ns_ = 0;
}

}  // namespace turf::simproto
