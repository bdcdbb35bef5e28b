// Under DDS Security, Fast DDS 2.9.1 (Debian 12's) sometimes never finishes one pair of participants' handshake
// (README, Access control: known limit); a bridge whose pair with turf-sim stalls waits for it for good. A new
// participant starts new handshakes, so a bridge that is waiting for turf-sim when its participant reports a stalled
// authentication (dds::Participant::AuthenticationsNow, after ParticipantOptions::authentication_timeout) restarts
// itself (RequestRestart, process.h).
//
// Only while waiting: announcements are not authenticated, so anyone on the network can make a participant stall
// (announce one that never answers). A bridge that has turf-sim is never restarted by that, and a waiting one has
// nothing yet to lose; a stall told while the bridge had turf-sim does not count later.
#pragma once

#include <cstdint>

#include "dds/participant.h"

namespace turf {

class StalledAuthenticationRestart {
 public:
  // Call it now and then with the participant's authentications and whether the bridge is waiting for turf-sim
  // (has no turf-sim now). True when a stall was told while waiting: it then has logged why and called
  // RequestRestart().
  bool Check(const dds::Authentications& now, bool waiting);

 private:
  uint64_t stalled_seen_ = 0;  // stalls told before the bridge last had turf-sim
};

}  // namespace turf
