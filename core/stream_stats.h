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
  void Save(StateWriter& out) const {
    out.Put(sent_);
    out.Put(lost_);
    out.Put(delivered_);
    out.Put(sum_);
    out.Put(sum_sq_);
  }
  void Restore(StateReader& in) {
    sent_ = in.Get<uint64_t>();
    lost_ = in.Get<uint64_t>();
    delivered_ = in.Get<uint64_t>();
    sum_ = in.Get<double>();
    sum_sq_ = in.Get<double>();
  }
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
  uint64_t sent_ = 0, lost_ = 0, delivered_ = 0;
  double sum_ = 0.0, sum_sq_ = 0.0;
};

}  // namespace turf
