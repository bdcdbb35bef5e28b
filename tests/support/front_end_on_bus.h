// A front-end (a bridge serving its protocol's clients) and turf-sim's legged node in lockstep on one in-memory bus,
// each on its own thread: the set-up of the in-process front-end tests (RCSSServerMJ, HLVS). Link turf_sim_node.
#pragma once

#include <unistd.h>

#include <functional>
#include <memory>
#include <string>
#include <utility>

#include "dds/memory_bus.h"
#include "tests/sim/sim_harness.h"
#include "tests/support/in_process.h"

namespace turf::test {

template <class Bridge>
class FrontEndOnBus {
 public:
  // `name`: the bus's, made unique per process; `make` builds the front-end on the bus, once turf-sim runs `scene`.
  FrontEndOnBus(const std::string& name, LeggedScene scene,
                const std::function<std::unique_ptr<Bridge>(dds::Bus&)>& make)
      : bus_(name + std::to_string(getpid())), sim_(std::move(scene), bus_, TimeMode::kLockstep), bridge_(make(bus_)) {}

  Bridge& bridge() { return bridge_.node(); }

 private:
  dds::MemoryBus bus_;
  SimUnderTest sim_;
  OnThread<Bridge> bridge_;
};

}  // namespace turf::test
