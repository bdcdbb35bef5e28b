// ROS 2's camera messages (idl/ros/RosImage.idl) from a rendered, encoded frame: sensor_msgs/Image (rgb8,
// yuv422_yuy2), CompressedImage (jpeg) and CameraInfo (the pinhole's intrinsics, no distortion). The header's
// stamp is the simulation time of the state the frame shows; frame_id is "<robot>/<camera>".
#pragma once

#include <turf/idl/RosImagePubSubTypes.h>

#include <cstdint>
#include <vector>

#include "core/camera/camera_model.h"

namespace turf {

std_msgs::msg::dds_::Header_ CameraHeader(const CameraSpec& camera, int64_t sim_time_ns);
sensor_msgs::msg::dds_::Image_ ImageMessage(const CameraSpec& camera, int64_t sim_time_ns, std::vector<uint8_t> bytes);
sensor_msgs::msg::dds_::CompressedImage_ CompressedMessage(const CameraSpec& camera, int64_t sim_time_ns,
                                                           std::vector<uint8_t> bytes);
sensor_msgs::msg::dds_::CameraInfo_ CameraInfoMessage(const CameraSpec& camera, int64_t sim_time_ns);

}  // namespace turf
