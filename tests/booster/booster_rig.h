// What the Booster SDK bridge tests share: turf-sim in lockstep on a memory bus, a control client that steps it,
// and the Booster SDK bridge (its first robot on `domain`) running on a thread of its own.
#pragma once

#include <chrono>
#include <memory>

#include "dds/control_client.h"
#include "dds/memory_bus.h"
#include "participants/booster_bridge/booster_sdk_bridge.h"
#include "tests/sim/sim_harness.h"
#include "tests/support/in_process.h"
#include "tests/support/legged_scene.h"

namespace turf::test {

// configs/scenes/t1_stand.yaml (Menagerie's home pose) without sensor noise.
inline LeggedScene IdealT1Stand() {
  LeggedScene scene = LoadScene("t1_stand.yaml");
  scene.realism = {};
  return scene;
}

class BoosterRig {
 public:
  BoosterRig(LeggedScene scene, int domain)
      : bus_("mem"),
        sim_(std::move(scene), bus_, TimeMode::kLockstep),
        client_(bus_, "test"),
        bridge_(Bridge(domain, bus_)) {}

  // Steps turf-sim `frames` frames and waits for its reply.
  dds::ControlOutcome Step(uint32_t frames) { return client_.Call(StepRequest(frames), std::chrono::seconds(20)); }
  BoosterSdkBridge& bridge() { return bridge_.node(); }
  SimNode& sim() { return sim_.node(); }

 private:
  static std::unique_ptr<BoosterSdkBridge> Bridge(int domain, dds::Bus& bus) {
    BoosterSdkOptions o;
    o.domain = domain;
    return std::make_unique<BoosterSdkBridge>(o, bus);
  }

  dds::MemoryBus bus_;
  SimUnderTest sim_;
  dds::ControlClient client_;
  OnThread<BoosterSdkBridge> bridge_;
};

}  // namespace turf::test
