#include "participants/sim/sim_host.h"

#include <spdlog/spdlog.h>

#include <atomic>
#include <stdexcept>
#include <thread>
#include <type_traits>
#include <utility>
#include <vector>

#include "dds/fanout_bus.h"
#include "dds/memory_bus.h"
#include "dds/participant.h"
#include "participants/sim/sim_node.h"

namespace turf {

class SimHost::Impl {
 public:
  template <class SceneKind>
  Impl(SceneKind scene, SimNodeOptions options, InProcessFrontEnds front_ends)
      : dds_(DdsOptions(options)), local_(options.prefix), bus_(dds_, local_), node_(std::move(scene), options, bus_) {
    constexpr bool kLegged = std::is_same_v<SceneKind, LeggedScene>;
    if (front_ends.simproto) {
      if (kLegged) throw std::invalid_argument("the SSL simulation protocol needs an SSL scene, not a legged one");
      simproto_ = std::make_unique<SimprotoBridge>(std::move(*front_ends.simproto), local_);
    }
    if (front_ends.simspark) {
      if (!kLegged) throw std::invalid_argument("the SimSpark front-end needs a legged scene, not an SSL one");
      simspark_ = std::make_unique<SimSparkBridge>(std::move(*front_ends.simspark), local_);
    }
    if (front_ends.rcssservermj) {
      if (!kLegged) throw std::invalid_argument("the RCSSServerMJ front-end needs a legged scene, not an SSL one");
      rcssservermj_ = std::make_unique<RcssServerMjBridge>(std::move(*front_ends.rcssservermj), local_);
    }
    if (front_ends.booster) {
      if (!kLegged) throw std::invalid_argument("the Booster SDK's topics need a legged scene, not an SSL one");
      booster_ = std::make_unique<BoosterSdkBridge>(*front_ends.booster, local_);
    }
  }

  // The front-ends' threads are stopped and joined before Run returns, and the front-ends are destroyed before the
  // node and the buses (members in reverse order).
  void Run(const std::function<bool()>& stop) {
    std::atomic<bool> done{false};             // the node's loop ended
    std::atomic<bool> front_end_ended{false};  // a front-end's loop ended by itself
    auto front_end_stop = [&] { return done.load() || stop(); };
    std::vector<std::thread> threads;
    if (simproto_) {
      spdlog::info("serving the SSL simulation protocol in this process (on an in-memory bus, no DDS hop):");
      threads.emplace_back([&] {
        simproto_->Run(front_end_stop);
        front_end_ended.store(true);
      });
    }
    if (simspark_) {
      spdlog::info("serving SimSpark agents and monitors in this process (on an in-memory bus, no DDS hop):");
      threads.emplace_back([&] {
        simspark_->Run(front_end_stop);
        front_end_ended.store(true);
      });
    }
    if (rcssservermj_) {
      spdlog::info(
          "serving RCSSServerMJ agents and monitor commands in this process (on an in-memory bus, no DDS "
          "hop):");
      threads.emplace_back([&] {
        rcssservermj_->Run(front_end_stop);
        front_end_ended.store(true);
      });
    }
    if (booster_) {
      spdlog::info("serving the Booster SDK's topics for every T1 and K1 in this process:");
      threads.emplace_back([&] { booster_->Run(front_end_stop); });
    }
    node_.Run([&] { return stop() || front_end_ended.load(); });
    done.store(true);
    for (std::thread& t : threads) t.join();
  }

  SimNode& node() { return node_; }
  dds::Participant& participant() { return dds_; }
  SimprotoBridge* simproto() { return simproto_.get(); }
  SimSparkBridge* simspark() { return simspark_.get(); }
  RcssServerMjBridge* rcssservermj() { return rcssservermj_.get(); }
  BoosterSdkBridge* booster() { return booster_.get(); }

 private:
  dds::Participant dds_;
  dds::MemoryBus local_;
  dds::FanoutBus bus_;
  SimNode node_;
  std::unique_ptr<SimprotoBridge> simproto_;
  std::unique_ptr<SimSparkBridge> simspark_;
  std::unique_ptr<RcssServerMjBridge> rcssservermj_;
  std::unique_ptr<BoosterSdkBridge> booster_;
};

SimHost::SimHost(Scene scene, SimNodeOptions options, InProcessFrontEnds front_ends)
    : impl_(std::make_unique<Impl>(std::move(scene), std::move(options), std::move(front_ends))) {}
SimHost::SimHost(LeggedScene scene, SimNodeOptions options, InProcessFrontEnds front_ends)
    : impl_(std::make_unique<Impl>(std::move(scene), std::move(options), std::move(front_ends))) {}
SimHost::~SimHost() = default;
void SimHost::Run(const std::function<bool()>& stop) { impl_->Run(stop); }
SimNode& SimHost::node() { return impl_->node(); }
dds::Participant& SimHost::participant() { return impl_->participant(); }
SimprotoBridge* SimHost::simproto() { return impl_->simproto(); }
SimSparkBridge* SimHost::simspark() { return impl_->simspark(); }
RcssServerMjBridge* SimHost::rcssservermj() { return impl_->rcssservermj(); }
BoosterSdkBridge* SimHost::booster() { return impl_->booster(); }

}  // namespace turf
