#include "participants/common/stalled_authentication.h"

#include <spdlog/spdlog.h>

#include "participants/common/process.h"

namespace turf {

bool StalledAuthenticationRestart::Check(const dds::Authentications& now, bool waiting) {
  if (!waiting) {
    stalled_seen_ = now.stalled;
    return false;
  }
  if (now.stalled <= stalled_seen_) return false;
  spdlog::warn(
      "still waiting for turf-sim, and {} DDS authentication(s) of this participant stalled (named above): restarting "
      "this process, whose new participant starts new handshakes (README, Access control: known limit)",
      now.stalled - stalled_seen_);
  stalled_seen_ = now.stalled;
  RequestRestart();
  return true;
}

}  // namespace turf
