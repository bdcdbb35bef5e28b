#include "participants/sim/stats_report.h"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

namespace turf {

idl::SensorStats StatsToIdl(const StreamReport& report) {
  idl::SensorStats out;
  out.sim_time_ns(report.time_ns);
  out.window_s(report.window_s);
  for (const auto& [name, w] : report.streams) {
    idl::StreamStats s;
    s.name(name);
    s.rate_hz(w.delivered / report.window_s);
    s.sent(w.sent);
    s.lost(w.lost);
    s.loss_ratio(w.sent > 0 ? static_cast<double>(w.lost) / w.sent : 0.0);
    s.latency_mean(w.latency_mean);
    s.latency_stddev(w.latency_stddev);
    out.streams().push_back(s);
  }
  return out;
}

void ReportStreams(const StreamReport& report) {
  std::string streams;
  for (const auto& [name, w] : report.streams) {
    if (w.sent == 0) continue;
    const double loss = 100.0 * static_cast<double>(w.lost) / w.sent;
    streams += fmt::format(" {} {:.0f}/s loss {:.1f}% latency {:.1f}+-{:.1f}ms;", name, w.delivered / report.window_s,
                           loss, w.latency_mean * 1e3, w.latency_stddev * 1e3);
  }
  if (!streams.empty()) spdlog::info("streams (last second of sim time):{}", streams);
}

}  // namespace turf
