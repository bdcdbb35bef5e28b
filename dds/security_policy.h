// Who may publish and subscribe what under DDS Security (issue 19): the identities `turf security init` makes and
// what each one's signed permissions document allows, as one table (kIdentities) over the topic table (topics.h).
// The permissions and governance documents are generated from it here, and tests check them against it.
// No Fast DDS and no files: pure text.
//
// Identities (one directory each under the security directory, see participants/launcher/security_command.h):
//   sim                         turf-sim: publishes what it publishes, reads the commands and control
//   vision-bridge, grsim-bridge, simproto-bridge, simspark-bridge
//                               the bridges, run by the operator: read everything, publish the command topics
//                               and control (their own clients' allowlists decide which team may use them)
//   blue, yellow                a team's own software on DDS: publishes its own team's commands; reads the
//                               clock, the field, the camera detections, its own feedback, the legged sensor
//                               streams. In the lab profile also the ground-truth world state and control (pause,
//                               teleport); in the tournament profile neither.
//   render                      turf-render: reads the legged state and scene, publishes the camera topics
//                               (camera_topics.h; every other identity may read them: they are what a robot sees)
//   operator                    the match's operator (turf-viewer, scripts): reads everything, publishes control
//   observer                    reads everything, publishes nothing
//
// Limits of what DDS permissions can say: the legged topics (robots/joint_command and the sensor streams) carry
// every robot of both teams in one topic, so a team identity may publish joint commands for either team's robots;
// per-team legged topics would be needed to separate them.
#pragma once

#include <string>
#include <vector>

namespace turf::dds {

enum class SecurityProfile {
  kLab,         // teams may read the world state and send control requests
  kTournament,  // teams read only what a team reads at a match; only the operator controls
};

enum class Protection {
  kEncrypt,  // authentication, access control, and every topic's data and discovery encrypted (AES-GCM)
  kNone,     // authentication and access control only: nothing encrypted (to measure what encryption costs)
};

struct IdentityGrant {
  std::string name;                    // directory and certificate name: "blue"
  std::vector<std::string> publish;    // topic suffixes (topics.h), without the prefix
  std::vector<std::string> subscribe;  // likewise
  // The camera topics (camera_topics.h), by kind: rt/<prefix>/*/*/<kind> in the permissions.
  bool publish_cameras = false;
  bool subscribe_cameras = false;
};

// Every identity's name, in the table's order.
std::vector<std::string> IdentityNames();
// The grant of `name` under `profile`; throws std::invalid_argument for a name that is not an identity.
IdentityGrant GrantOf(const std::string& name, SecurityProfile profile);

// The certificate subject of an identity, as in its certificate and its permissions document:
// "CN=turf blue,O=turf".
std::string SubjectOf(const std::string& identity);

// The governance document (unsigned): domains 0..232, no unauthenticated participants, join and read/write access
// control on every topic, with `protection`.
std::string GovernanceXml(Protection protection);
// The permissions document (unsigned) of `identity` for topics under `prefix` on domains 0..232: its grant's
// topics allowed, everything else denied. Valid from `not_before` to `not_after` (e.g. "2026-01-01T00:00:00").
std::string PermissionsXml(const std::string& identity, SecurityProfile profile, const std::string& prefix,
                           const std::string& not_before, const std::string& not_after);

}  // namespace turf::dds
