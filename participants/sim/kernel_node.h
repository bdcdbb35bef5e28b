// What turf-sim's SSL and legged nodes share around their kernel (SslKernel,
// LeggedKernel): the bus (a participant of their own unless one is given),
// the control loop that paces the kernel and serves control requests, the
// kernel's publisher, and the ControlLoop::Node operations that are the same
// for every kind of kernel. A node adds its command readers, inputs and
// outputs (sim_node.cpp, legged_node.cpp).
#pragma once

#include <spdlog/spdlog.h>

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <utility>

#include "dds/bus.h"
#include "loader/realism_change.h"
#include "loader/realism_yaml.h"
#include "participants/sim/control_loop.h"
#include "participants/sim/sim_node.h"
#include "participants/sim/stats_report.h"

namespace turf {

template <class Kernel, class Publisher>
class KernelNode : public SimNode::Impl, protected ControlLoop::Node {
 public:
  SimNodeStats Stats() const override { return loop_.Stats(); }
  uint64_t Rejected(const std::string& kind) const override { return loop_.Rejected(kind); }

 protected:
  // `kind` names the scene kind in SceneIdentity ("ssl"); `timing` gives the
  // loop's step and publication rate for the kernel.
  template <class SceneKind>
  KernelNode(const char* kind, SceneKind scene, SimNodeOptions options, dds::Bus* bus,
             ControlLoop::Timing (*timing)(const Kernel&))
      : kind_(kind),
        options_(std::move(options)),
        kernel_(std::move(scene)),
        own_bus_(bus != nullptr ? nullptr : MakeNodeParticipant(options_)),
        bus_(bus != nullptr ? *bus : *own_bus_),
        loop_(bus_, options_, timing(kernel_), *this),
        publisher_(bus_) {}

  // --- ControlLoop::Node: alike for every kernel ---

  int64_t TimeNs() const override { return kernel_.time_ns(); }
  uint64_t Frame() const override { return kernel_.frame(); }
  void Step() override { kernel_.Step(); }
  void PublishState() override { publisher_.PublishState(kernel_); }

  ControlAnswer ChangeRealism(const RealismChange& change) override {
    const RealismChangeResult changed = ApplyRealismChange(kernel_.realism(), change, realism_dir_);
    if (!changed.ok()) return {ControlErrorOf(changed.error), changed.reason};
    if (std::string e = kernel_.SetRealism(changed.realism); !e.empty()) return {idl::CONTROL_INVALID_REALISM, e};
    spdlog::info("sensor realism changed ({})", DescribeRealismChange(change));
    return {};
  }

  std::string SaveKernel() const override { return kernel_.Save(); }
  std::string RestoreKernel(std::string_view snapshot) override { return kernel_.Restore(snapshot); }
  std::string SceneIdentity() const override {
    return fmt::format("{} scene '{}' seed {}", kind_, kernel_.scene().name, kernel_.scene().seed);
  }

  // The loop's status line with the node's own `counters`, then the streams'
  // statistics of the last window.
  void ReportStatusWith(const std::string& counters) const {
    loop_.ReportStatusLine(counters);
    ReportStreams(publisher_.last_stats());
  }

  const char* kind_;
  SimNodeOptions options_;
  Kernel kernel_;
  std::unique_ptr<dds::Bus> own_bus_;  // when the node makes its own participant
  dds::Bus& bus_;
  ControlLoop loop_;  // before the readers: their callbacks wake it
  Publisher publisher_;
  std::string realism_dir_ = DefaultRealismDir();
};

}  // namespace turf
