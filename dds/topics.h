// Every turf DDS topic, once. Participants, tests and docs derive names and
// QoS profile names from this table; the QoS itself is in configs/qos/turf_qos.xml.
#pragma once

#include <string>

namespace turf::dds {

enum class Topic {
  kClock,
  kWorldState,
  kSslField,
  kSslCamera,
  kSslCommandBlue,
  kSslCommandYellow,
  kSslFeedbackBlue,
  kSslFeedbackYellow,
  kControl,
  kControlReply,
  kStats,
  kRobotJointState,
  kRobotImu,
  kRobotForce,
  kRobotJointCommand,
  kRobotLinks,
  kLeggedScene,
  kRobotsState,
};

struct TopicInfo {
  Topic topic;
  const char* suffix;   // full name: <prefix>/<suffix>
  const char* profile;  // data_writer / data_reader profile in the QoS file
  const char* type;     // IDL type (turf::idl::...)
  const char* what;
};

inline constexpr TopicInfo kTopics[] = {
    {Topic::kClock, "clock", "turf.state", "Clock", "simulation time, with every world state"},
    {Topic::kWorldState, "world_state", "turf.state", "WorldState", "ground truth of ball and robots"},
    {Topic::kSslField, "ssl/field", "turf.field", "SslField", "field geometry, ball model, cameras (latched)"},
    {Topic::kSslCamera, "ssl/camera", "turf.sensor", "CameraFrame", "per-camera detections, keyed by camera"},
    {Topic::kSslCommandBlue, "ssl/command/blue", "turf.command", "SslRobotCommand", "blue robot commands"},
    {Topic::kSslCommandYellow, "ssl/command/yellow", "turf.command", "SslRobotCommand", "yellow robot commands"},
    {Topic::kSslFeedbackBlue, "ssl/feedback/blue", "turf.feedback", "SslRobotFeedback", "blue ball contact, kicks"},
    {Topic::kSslFeedbackYellow, "ssl/feedback/yellow", "turf.feedback", "SslRobotFeedback",
     "yellow ball contact, kicks"},
    {Topic::kControl, "control", "turf.control", "SimControl", "teleport, pause, step, reset, time mode"},
    {Topic::kControlReply, "control_reply", "turf.reply", "SimControlReply", "what a control request did"},
    {Topic::kStats, "stats", "turf.state", "SensorStats", "rate, loss and latency of each modelled stream"},
    {Topic::kRobotJointState, "robots/joint_state", "turf.state", "JointState",
     "legged robots' joints, keyed by robot"},
    {Topic::kRobotImu, "robots/imu", "turf.state", "ImuState", "legged robots' gyro, accelerometer, orientation"},
    {Topic::kRobotForce, "robots/force", "turf.state", "ForceState", "legged robots' touch and force sensors"},
    {Topic::kRobotJointCommand, "robots/joint_command", "turf.command", "JointCommand",
     "legged robots' joint targets, keyed by robot"},
    {Topic::kRobotLinks, "robots/links", "turf.state", "LinkState", "legged robots' body poses, keyed by robot"},
    {Topic::kLeggedScene, "legged/scene", "turf.field", "LeggedSceneInfo",
     "legged scene: robots' shapes, 3D field size (latched)"},
    {Topic::kRobotsState, "robots/state", "turf.state", "LeggedState",
     "all legged robots' joints, IMU, forces and links of one frame, with the ball"},
};

const TopicInfo& Info(Topic topic);
std::string TopicName(const std::string& prefix, Topic topic);

}  // namespace turf::dds
