#include "dds/security_policy.h"

#include <initializer_list>
#include <stdexcept>

#include "dds/camera_topics.h"
#include "dds/topics.h"

namespace turf::dds {

namespace {

std::string Suffix(Topic topic) { return topic.info().suffix; }

std::vector<std::string> Suffixes(const std::vector<Topic>& topics) {
  std::vector<std::string> out;
  for (Topic t : topics) out.push_back(Suffix(t));
  return out;
}

// Every topic of the table with one of `directions` (as turf-sim sees them).
std::vector<std::string> WithDirection(std::initializer_list<Direction> directions) {
  std::vector<std::string> out;
  for (const TopicInfo& t : kTopics)
    for (Direction d : directions)
      if (t.direction == d) out.push_back(t.suffix);
  return out;
}

std::vector<std::string> Everything() {
  return WithDirection({Direction::kPublished, Direction::kLatched, Direction::kSubscribed});
}

IdentityGrant Team(const std::string& name, SecurityProfile profile) {
  const bool blue = name == "blue";
  IdentityGrant g{name, Suffixes({blue ? Topic::kSslCommandBlue : Topic::kSslCommandYellow, Topic::kRobotJointCommand}),
                  Suffixes({Topic::kClock, Topic::kSslField, Topic::kSslCamera,
                            blue ? Topic::kSslFeedbackBlue : Topic::kSslFeedbackYellow, Topic::kStats,
                            Topic::kLeggedScene, Topic::kRobotJointState, Topic::kRobotImu, Topic::kRobotForce})};
  if (profile == SecurityProfile::kLab) {
    // Ground truth and the control plane: a lab's convenience, not a match's.
    for (Topic t : std::initializer_list<Topic>{Topic::kWorldState, Topic::kRobotsState, Topic::kRobotLinks,
                                                Topic::kControlReply})
      g.subscribe.push_back(Suffix(t));
    g.publish.push_back(Suffix(Topic::kControl));
  }
  return g;
}

// The bridges write what turf-sim reads; and cameras/control (the HLVS bridge, which runs as simspark-bridge, asks
// turf-render for the cameras its clients enable).
IdentityGrant Bridge(const std::string& name) {
  IdentityGrant g{name, WithDirection({Direction::kSubscribed}), Everything()};
  g.publish.push_back(kCameraControlSuffix);
  return g;
}

const char* const kNames[] = {"sim",  "vision-bridge", "grsim-bridge", "simproto-bridge", "simspark-bridge",
                              "blue", "yellow",        "operator",     "observer",        "render"};

IdentityGrant Render() {
  IdentityGrant g{"render", {}, Suffixes({Topic::kClock, Topic::kLeggedScene, Topic::kRobotsState})};
  g.subscribe.push_back(kCameraControlSuffix);  // cameras on and off at run time
  g.publish_cameras = true;
  return g;
}

// Every identity but turf-sim's reads the camera topics.
IdentityGrant WithCameras(IdentityGrant g) {
  g.subscribe_cameras = true;
  return g;
}

std::string JoinCameras(const std::string& prefix, const std::string& indent) {
  std::string out;
  for (CameraTopic t : {CameraTopic::kImage, CameraTopic::kCompressed, CameraTopic::kCameraInfo})
    out += indent + "<topic>" + CameraTopicPattern(prefix, t) + "</topic>\n";
  return out;
}

std::string Join(const std::vector<std::string>& topics, const std::string& prefix, const std::string& indent) {
  std::string out;
  for (const std::string& t : topics) out += indent + "<topic>" + prefix + "/" + t + "</topic>\n";
  return out;
}

constexpr const char* kDomains = "<domains><id_range><min>0</min><max>232</max></id_range></domains>";

}  // namespace

std::vector<std::string> IdentityNames() { return {std::begin(kNames), std::end(kNames)}; }

IdentityGrant GrantOf(const std::string& name, SecurityProfile profile) {
  if (name == "sim")
    return {name, WithDirection({Direction::kPublished, Direction::kLatched}), WithDirection({Direction::kSubscribed})};
  if (name == "vision-bridge" || name == "grsim-bridge" || name == "simproto-bridge" || name == "simspark-bridge")
    return WithCameras(Bridge(name));
  if (name == "blue" || name == "yellow") return WithCameras(Team(name, profile));
  if (name == "operator") {
    IdentityGrant g = WithCameras({name, Suffixes({Topic::kControl}), Everything()});
    g.publish.push_back(kCameraControlSuffix);  // switches turf-render's cameras
    return g;
  }
  if (name == "observer") return WithCameras({name, {}, Everything()});
  if (name == "render") return Render();
  std::string known;
  for (const char* n : kNames) known += std::string(known.empty() ? "" : ", ") + n;
  throw std::invalid_argument("'" + name + "' is not a turf security identity (one of: " + known + ")");
}

std::string SubjectOf(const std::string& identity) { return "CN=turf " + identity + ",O=turf"; }

std::string GovernanceXml(Protection protection) {
  const std::string kind = protection == Protection::kEncrypt ? "ENCRYPT" : "NONE";
  const std::string on = protection == Protection::kEncrypt ? "true" : "false";
  return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
         "<dds xmlns:xsi=\"http://www.w3.org/2001/XMLSchema-instance\">\n"
         "  <domain_access_rules>\n"
         "    <domain_rule>\n"
         "      " +
         std::string(kDomains) +
         "\n"
         "      <allow_unauthenticated_participants>false</allow_unauthenticated_participants>\n"
         "      <enable_join_access_control>true</enable_join_access_control>\n"
         "      <discovery_protection_kind>" +
         kind +
         "</discovery_protection_kind>\n"
         "      <liveliness_protection_kind>" +
         kind +
         "</liveliness_protection_kind>\n"
         "      <rtps_protection_kind>" +
         kind +
         "</rtps_protection_kind>\n"
         "      <topic_access_rules>\n"
         "        <topic_rule>\n"
         "          <topic_expression>*</topic_expression>\n"
         "          <enable_discovery_protection>" +
         on +
         "</enable_discovery_protection>\n"
         "          <enable_liveliness_protection>" +
         on +
         "</enable_liveliness_protection>\n"
         "          <enable_read_access_control>true</enable_read_access_control>\n"
         "          <enable_write_access_control>true</enable_write_access_control>\n"
         "          <metadata_protection_kind>" +
         kind +
         "</metadata_protection_kind>\n"
         "          <data_protection_kind>" +
         kind +
         "</data_protection_kind>\n"
         "        </topic_rule>\n"
         "      </topic_access_rules>\n"
         "    </domain_rule>\n"
         "  </domain_access_rules>\n"
         "</dds>\n";
}

std::string PermissionsXml(const std::string& identity, SecurityProfile profile, const std::string& prefix,
                           const std::string& not_before, const std::string& not_after) {
  const IdentityGrant g = GrantOf(identity, profile);
  std::string rules;
  const std::string indent = "          ";
  const std::string publish = Join(g.publish, prefix, indent) + (g.publish_cameras ? JoinCameras(prefix, indent) : "");
  const std::string subscribe =
      Join(g.subscribe, prefix, indent) + (g.subscribe_cameras ? JoinCameras(prefix, indent) : "");
  if (!publish.empty()) rules += "        <publish><topics>\n" + publish + "        </topics></publish>\n";
  if (!subscribe.empty()) rules += "        <subscribe><topics>\n" + subscribe + "        </topics></subscribe>\n";
  return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
         "<dds xmlns:xsi=\"http://www.w3.org/2001/XMLSchema-instance\">\n"
         "  <permissions>\n"
         "    <grant name=\"turf-" +
         identity +
         "\">\n"
         "      <subject_name>" +
         SubjectOf(identity) +
         "</subject_name>\n"
         "      <validity><not_before>" +
         not_before + "</not_before><not_after>" + not_after +
         "</not_after></validity>\n"
         "      <allow_rule>\n"
         "        " +
         std::string(kDomains) + "\n" + rules +
         "      </allow_rule>\n"
         "      <default>DENY</default>\n"
         "    </grant>\n"
         "  </permissions>\n"
         "</dds>\n";
}

}  // namespace turf::dds
