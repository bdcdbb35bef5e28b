// Declares dds::Bus (bus.h) for headers that only take one by reference: a participant's constructor on a
// dds::MemoryBus, say. Like <iosfwd>.
#pragma once

namespace turf::dds {
class Bus;
}  // namespace turf::dds
