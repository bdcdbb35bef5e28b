// Every turf DDS topic, once: TURF_DDS_TOPICS below. Everything else derives from that list:
//  - the constants dds::Topic::kClock, ... Each is a TopicDef<idl::ClockPubSubType> and so carries its DDS
//    type: Participant::MakeWriter<idl::WrongPubSubType>(dds::Topic::kClock) does not compile;
//  - the table kTopics (name, QoS profile, type name, direction, description), indexed by TopicId;
//  - the README's topic table (TopicsMarkdown(); tests/dds checks README.md against it);
//  - the start-up log lines of a participant's writers and readers (EndpointLine(), Participant::TopicLines()).
// The QoS itself is in configs/qos/turf_qos.xml. This header needs no Fast DDS: the PubSubTypes are only
// declared here (tests/dds checks them against the generated ones).
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <tuple>

// X(constant, IDL type, name, QoS profile, direction, what)
//  - IDL type: turf::idl::<type>, registered with DDS as "turf::idl::<type>" by turf::idl::<type>PubSubType;
//  - name: the full topic name is <prefix>/<name>;
//  - QoS profile: the data_writer and data_reader profile in the QoS file;
//  - direction, as turf-sim sees it: kPublished, kLatched (published; a late reader gets the last sample),
//    kSubscribed.
// Descriptions are Markdown (they go into README.md) and must not contain '|'.
#define TURF_DDS_TOPICS(X)                                                                                            \
  X(kClock, Clock, "clock", "turf.state", kPublished,                                                                 \
    "with every world state: sim time, frame, paused, time mode, measured real-time factor, run epoch (Unix ns of "   \
    "sim time 0)")                                                                                                    \
  X(kWorldState, WorldState, "world_state", "turf.state", kPublished,                                                 \
    "every 1/`rates.world_state_hz` of sim time (100 Hz): ball and every robot's pose and velocity")                  \
  X(kSslField, SslField, "ssl/field", "turf.field", kLatched, "field geometry, ball model, camera layout")            \
  X(kSslCamera, CameraFrame, "ssl/camera", "turf.sensor", kPublished,                                                 \
    "one sample per camera per frame (60 Hz), keyed by camera: what that camera sees")                                \
  X(kSslCommandBlue, SslRobotCommand, "ssl/command/blue", "turf.command", kSubscribed,                                \
    "blue robots' commands; the newest command per robot counts")                                                     \
  X(kSslCommandYellow, SslRobotCommand, "ssl/command/yellow", "turf.command", kSubscribed,                            \
    "yellow robots' commands; the newest command per robot counts")                                                   \
  X(kSslFeedbackBlue, SslRobotFeedback, "ssl/feedback/blue", "turf.feedback", kPublished,                             \
    "on change: blue robots' ball contact, kick count")                                                               \
  X(kSslFeedbackYellow, SslRobotFeedback, "ssl/feedback/yellow", "turf.feedback", kPublished,                         \
    "on change: yellow robots' ball contact, kick count")                                                             \
  X(kControl, SimControl, "control", "turf.control", kSubscribed,                                                     \
    "teleport ball/robot (incl. on/off field), pause, resume, step N, reset, time mode")                              \
  X(kControlReply, SimControlReply, "control_reply", "turf.reply", kPublished,                                        \
    "one per request: OK, or REJECTED with the reason")                                                               \
  X(kStats, SensorStats, "stats", "turf.state", kPublished,                                                           \
    "every second of sim time: rate, loss and latency of each modelled stream")                                       \
  X(kRobotJointState, JointState, "robots/joint_state", "turf.state", kPublished,                                     \
    "legged scenes, every 1/`rates.joint_state_hz` of sim time (50 Hz), through the joints' modelled link: each "     \
    "robot's joints, keyed by robot")                                                                                 \
  X(kRobotImu, ImuState, "robots/imu", "turf.state", kPublished,                                                      \
    "legged scenes, at the joint-state rate, through the IMU's modelled link: gyro, accelerometer, orientation; "     \
    "the root body's true pose and velocity")                                                                         \
  X(kRobotForce, ForceState, "robots/force", "turf.state", kPublished,                                                \
    "legged scenes, at the joint-state rate, through the touch sensors' modelled link: touch and force sensors")      \
  X(kRobotJointCommand, JointCommand, "robots/joint_command", "turf.command", kSubscribed,                            \
    "legged scenes: joint targets, keyed by robot")                                                                   \
  X(kRobotLinks, LinkState, "robots/links", "turf.state", kPublished,                                                 \
    "legged scenes, at the joint-state rate: each robot's body poses, keyed by robot")                                \
  X(kLeggedScene, LeggedSceneInfo, "legged/scene", "turf.field", kLatched,                                            \
    "legged scenes: the robots' shapes, 3D field size")                                                               \
  X(kSimRun, SimRun, "sim/run", "turf.field", kLatched,                                                               \
    "once, latched: the scene file's text and directory, realism and seed, for `turf replay --resimulate`")           \
  X(kAppliedInputs, AppliedInputs, "sim/applied_inputs", "turf.control", kPublished,                                  \
    "before a step, when inputs were taken since the last: the step count, sim time and each input sample's "         \
    "CDR, in the order applied")                                                                                      \
  X(kRobotsState, LeggedState, "robots/state", "turf.state", kPublished,                                              \
    "legged scenes, at the joint-state rate: all robots' joints, IMU, forces and links of one frame, with the ball, " \
    "the pairs of robots touching and each robot's last touch of the ball")

namespace turf::idl {
#define TURF_TOPIC_DECLARE_PUBSUB(constant, type, ...) \
  class type;                                          \
  class type##PubSubType;                              \
  type SampleOfPubSub(const type##PubSubType*);
TURF_DDS_TOPICS(TURF_TOPIC_DECLARE_PUBSUB)
#undef TURF_TOPIC_DECLARE_PUBSUB
}  // namespace turf::idl

namespace turf::dds {

// The sample type of a PubSubType (idl::Clock for idl::ClockPubSubType), without its Fast DDS header: the
// declarations above pair them (a function may be declared twice, where two topics share a type; decltype
// of a call needs no complete type). dds/participant.cpp checks each against PubSubType::type.
template <class PubSub>
using SampleOf = decltype(idl::SampleOfPubSub(static_cast<const PubSub*>(nullptr)));

// Which row of kTopics; switch on Topic::id() where a topic is a runtime value.
enum class TopicId : std::size_t {
#define TURF_TOPIC_ID(constant, ...) constant,
  TURF_DDS_TOPICS(TURF_TOPIC_ID)
#undef TURF_TOPIC_ID
};

// A topic's direction as turf-sim sees it.
enum class Direction { kPublished, kLatched, kSubscribed };

struct TopicInfo {
  const char* constant;  // "kClock"
  const char* suffix;    // full name: <prefix>/<suffix>
  const char* profile;   // data_writer / data_reader profile in the QoS file
  const char* type;      // IDL type: "Clock" (turf::idl::Clock)
  const char* dds_type;  // type name registered with DDS: "turf::idl::Clock"
  Direction direction;   // as turf-sim sees it
  const char* what;      // Markdown, for README.md
};

inline constexpr TopicInfo kTopics[] = {
#define TURF_TOPIC_ROW(constant, type, suffix, profile, direction, what) \
  {#constant, suffix, profile, #type, "turf::idl::" #type, Direction::direction, what},
    TURF_DDS_TOPICS(TURF_TOPIC_ROW)
#undef TURF_TOPIC_ROW
};
inline constexpr std::size_t kTopicCount = sizeof(kTopics) / sizeof(kTopics[0]);

template <class PubSub>
class TopicDef;

// A topic as a value: store it, compare it, log it. Its constants, dds::Topic::kClock and so on, are
// TopicDefs, which also carry the topic's DDS type.
class Topic {
 public:
  constexpr TopicId id() const { return id_; }
  constexpr const TopicInfo& info() const { return kTopics[static_cast<std::size_t>(id_)]; }
  friend constexpr bool operator==(Topic a, Topic b) { return a.id_ == b.id_; }
  friend constexpr bool operator!=(Topic a, Topic b) { return a.id_ != b.id_; }

#define TURF_TOPIC_DECLARE(constant, type, ...) static const TopicDef<idl::type##PubSubType> constant;
  TURF_DDS_TOPICS(TURF_TOPIC_DECLARE)
#undef TURF_TOPIC_DECLARE

 protected:
  constexpr explicit Topic(TopicId id) : id_(id) {}

 private:
  TopicId id_;
};

// A topic and its DDS type, a turf::idl::...PubSubType. Only the constants of Topic exist: no code can
// pair a topic with another type.
template <class PubSub>
class TopicDef : public Topic {
 public:
  using PubSubType = PubSub;

 private:
  friend class Topic;
  constexpr explicit TopicDef(TopicId id) : Topic(id) {}
};

#define TURF_TOPIC_DEFINE(constant, type, ...) \
  inline constexpr TopicDef<idl::type##PubSubType> Topic::constant{TopicId::constant};
TURF_DDS_TOPICS(TURF_TOPIC_DEFINE)
#undef TURF_TOPIC_DEFINE

// Every topic, in table order, as values ...
inline constexpr std::array<Topic, kTopicCount> kAllTopics = {
#define TURF_TOPIC_VALUE(constant, ...) Topic::constant,
    TURF_DDS_TOPICS(TURF_TOPIC_VALUE)
#undef TURF_TOPIC_VALUE
};

// ... and with their types, for code generic over every topic (std::apply).
inline constexpr auto kTypedTopics = std::tuple_cat(std::tuple<>()
#define TURF_TOPIC_TYPED(constant, ...) , std::make_tuple(Topic::constant)
                                                        TURF_DDS_TOPICS(TURF_TOPIC_TYPED)
#undef TURF_TOPIC_TYPED
);

constexpr const TopicInfo& Info(Topic topic) { return topic.info(); }
std::string TopicName(const std::string& prefix, Topic topic);
const char* DirectionName(Direction direction);  // "published", "published, latched", "subscribed"

// A participant's use of a topic.
enum class Endpoint { kWriter, kReader };

// One start-up log line: "writes turf/clock (turf::idl::Clock, QoS profile turf.state)".
std::string EndpointLine(const std::string& prefix, Topic topic, Endpoint endpoint);

// The topic table of README.md (between its topic-table markers), one row per topic, then one per camera topic
// kind (camera_topics.h).
std::string TopicsMarkdown();

}  // namespace turf::dds
