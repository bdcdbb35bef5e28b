#include "participants/sim/sim_host.h"

#include <spdlog/spdlog.h>

#include <atomic>
#include <thread>
#include <utility>

#include "dds/fanout_bus.h"
#include "dds/memory_bus.h"
#include "dds/participant.h"
#include "participants/sim/sim_node.h"

namespace turf {

class SimHost::Impl {
 public:
  Impl(Scene scene, SimNodeOptions options, InProcessFrontEnds front_ends)
      : dds_({options.domain, options.name, options.prefix, options.qos_file}),
        local_(options.prefix),
        bus_(dds_, local_),
        node_(std::move(scene), options, bus_) {
    if (front_ends.simproto) simproto_ = std::make_unique<SimprotoBridge>(std::move(*front_ends.simproto), local_);
  }

  // The bridge's thread is stopped and joined before Run returns, and the bridge is destroyed before the node
  // and the buses (members in reverse order).
  void Run(const std::function<bool()>& stop) {
    std::atomic<bool> done{false};
    std::thread front_end;
    if (simproto_) {
      spdlog::info("serving the SSL simulation protocol in this process (on an in-memory bus, no DDS hop):");
      front_end = std::thread([&] { simproto_->Run([&] { return done.load() || stop(); }); });
    }
    node_.Run(stop);
    done.store(true);
    if (front_end.joinable()) front_end.join();
  }

  SimNode& node() { return node_; }
  SimprotoBridge* simproto() { return simproto_.get(); }

 private:
  dds::Participant dds_;
  dds::MemoryBus local_;
  dds::FanoutBus bus_;
  SimNode node_;
  std::unique_ptr<SimprotoBridge> simproto_;
};

SimHost::SimHost(Scene scene, SimNodeOptions options, InProcessFrontEnds front_ends)
    : impl_(std::make_unique<Impl>(std::move(scene), std::move(options), std::move(front_ends))) {}
SimHost::~SimHost() = default;
void SimHost::Run(const std::function<bool()>& stop) { impl_->Run(stop); }
SimNode& SimHost::node() { return impl_->node(); }
SimprotoBridge* SimHost::simproto() { return impl_->simproto(); }

}  // namespace turf
