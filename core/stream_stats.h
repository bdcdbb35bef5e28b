// What a modelled stream achieved over a window: samples sent into its link,
// lost there, delivered, and their delay. Feeds turf-sim's statistics topic.
#pragma once

#include <cmath>
#include <cstdint>

#include "core/state_io.h"

namespace turf {

struct StreamWindow {
  uint64_t sent = 0;
  uint64_t lost = 0;
  uint64_t delivered = 0;
  double latency_mean = 0.0;    // s
  double latency_stddev = 0.0;  // s
};

class StreamStats {
 public:
  void Sent() { ++sent_; }
  void Lost() { ++lost_; }
  void Delivered(double latency_s) {
    ++delivered_;
    sum_ += latency_s;
    sum_sq_ += latency_s * latency_s;
  }
  void Save(StateWriter& out) const { Fields(out, *this); }
  void Restore(StateReader& in) { Fields(in, *this); }
  // The window so far; starts a new one.
  StreamWindow Take() {
    StreamWindow w{sent_, lost_, delivered_, 0.0, 0.0};
    if (delivered_ > 0) {
      w.latency_mean = sum_ / delivered_;
      const double var = delivered_ > 1 ? (sum_sq_ - sum_ * sum_ / delivered_) / (delivered_ - 1) : 0.0;
      w.latency_stddev = std::sqrt(std::max(0.0, var));
    }
    *this = StreamStats{};
    return w;
  }

 private:
  template <class Io, class Self>
  static void Fields(Io& io, Self& self) {
    io(self.sent_, self.lost_, self.delivered_, self.sum_, self.sum_sq_);
  }

  uint64_t sent_ = 0, lost_ = 0, delivered_ = 0;
  double sum_ = 0.0, sum_sq_ = 0.0;
};

}  // namespace turf
