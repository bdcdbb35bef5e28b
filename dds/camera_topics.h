// The camera topics (issue 16), one set per declared camera, named as ROS 2 names them so that ROS 2 tools see
// them with no bridge: rt/<prefix>/<robot>/<camera>/<kind> is the ROS 2 topic /<prefix>/<robot>/<camera>/<kind>.
// They are not in TURF_DDS_TOPICS (topics.h): their names depend on the scene, their types are ROS 2's
// (idl/ros/RosImage.idl) and turf-render, not turf-sim, writes them, on a participant of its own for large samples
// (dds/vendor_participant.h: best effort, volatile, keep last 1, asynchronous and paced). The README's topic table
// lists them after turf-sim's rows (TopicsMarkdown()), and dds/security_policy.cpp grants them by pattern.
#pragma once

#include <cstddef>
#include <string>

// X(constant, kind, DDS type, what); descriptions are Markdown without '|'.
#define TURF_CAMERA_TOPICS(X)                                                                                       \
  X(kImage, "image_raw", "sensor_msgs::msg::dds_::Image_",                                                          \
    "cameras with encoding rgb8 or yuv422 (`yuv422_yuy2`), at each camera's `rate_hz` of sim time; `header.stamp` " \
    "is the simulation time of the state shown")                                                                    \
  X(kCompressed, "image_raw/compressed", "sensor_msgs::msg::dds_::CompressedImage_",                                \
    "cameras with encoding jpeg (`format` jpeg), as ROS's image_transport names it")                                \
  X(kCameraInfo, "camera_info", "sensor_msgs::msg::dds_::CameraInfo_",                                              \
    "with every image: size and pinhole intrinsics (no distortion), the same stamp")

namespace turf::dds {

enum class CameraTopic {
#define TURF_CAMERA_TOPIC_ENUM(constant, ...) constant,
  TURF_CAMERA_TOPICS(TURF_CAMERA_TOPIC_ENUM)
#undef TURF_CAMERA_TOPIC_ENUM
};

struct CameraTopicInfo {
  const char* kind;      // the last part of the name
  const char* dds_type;  // registered type name
  const char* what;
};

inline constexpr CameraTopicInfo kCameraTopics[] = {
#define TURF_CAMERA_TOPIC_ROW(constant, kind, type, what) {kind, type, what},
    TURF_CAMERA_TOPICS(TURF_CAMERA_TOPIC_ROW)
#undef TURF_CAMERA_TOPIC_ROW
};
inline constexpr std::size_t kCameraTopicCount = sizeof(kCameraTopics) / sizeof(kCameraTopics[0]);

// QoS of every camera topic, for logs and the README.
inline constexpr const char* kCameraTopicQos = "best effort, volatile, keep last 1";

const CameraTopicInfo& Info(CameraTopic topic);
// "rt/turf/t1/camera/image_raw" ("rt/t1/camera/image_raw" with an empty prefix).
std::string CameraTopicName(const std::string& prefix, const std::string& robot, const std::string& camera,
                            CameraTopic topic);
// The same with * for robot and camera: "rt/turf/*/*/image_raw", for DDS Security's permissions.
std::string CameraTopicPattern(const std::string& prefix, CameraTopic topic);

// turf-render's run-time switch (idl/ros/CameraControl.idl): <prefix>/cameras/control, turf's own type, on the
// same participant kind as the images (VendorParticipant: best effort, volatile, keep last); senders re-send their
// settings every kCameraControlResendSeconds.
inline constexpr const char* kCameraControlSuffix = "cameras/control";
inline constexpr const char* kCameraControlType = "turf::idl::CameraControl";
inline constexpr const char* kCameraControlWhat =
    "per camera, the newest counts: enable or disable it, at a rate of sim time (0: the scene's); senders (the HLVS "
    "bridge) re-send every second";
inline constexpr double kCameraControlResendSeconds = 1.0;
std::string CameraControlTopicName(const std::string& prefix);

}  // namespace turf::dds
