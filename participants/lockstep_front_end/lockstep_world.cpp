#include "participants/lockstep_front_end/lockstep_world.h"

#include "dds/participant.h"

namespace turf {

std::unique_ptr<LeggedLockstep> MakeLockstep(const ParticipantOptions& options, dds::Bus* bus, const char* client,
                                             bool need_force) {
  if (bus != nullptr) return std::make_unique<LeggedLockstep>(nullptr, *bus, client, need_force);
  auto own = std::make_unique<dds::Participant>(DdsOptions(options, client));
  dds::Bus& b = *own;
  return std::make_unique<LeggedLockstep>(std::move(own), b, client, need_force);
}

}  // namespace turf
