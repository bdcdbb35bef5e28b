// The kernels' statistics output: one report of every modelled stream at the
// step that closes each window (kStatsWindowNs) of simulation time.
#pragma once

#include <cstdint>
#include <optional>
#include <utility>

#include "core/state_io.h"
#include "kernel/stream_report.h"

namespace turf {

class StatsWindow {
 public:
  // The first window closes one window after sim time 0 (a kernel's Reset).
  void Reset() {
    next_ns_ = kStatsWindowNs;
    report_.reset();
  }
  // At the end of a step at `now_ns`: no report, unless a window closes now;
  // then one stamped `now_ns` with the streams `add_streams(StreamReport&)`
  // appends, and the next window starts.
  template <class AddStreams>
  void Collect(int64_t now_ns, const AddStreams& add_streams) {
    report_.reset();
    if (now_ns < next_ns_) return;
    StreamReport report;
    report.time_ns = now_ns;
    add_streams(report);
    report_ = std::move(report);
    next_ns_ = now_ns + kStatsWindowNs;
  }
  // Set in the step that closed a window.
  const std::optional<StreamReport>& report() const { return report_; }

  void Save(StateWriter& out) const { out.Put(next_ns_); }
  void Restore(StateReader& in) {
    next_ns_ = in.Get<int64_t>();
    report_.reset();
  }

 private:
  int64_t next_ns_ = kStatsWindowNs;
  std::optional<StreamReport> report_;
};

}  // namespace turf
