#include "participants/render/camera_messages.h"

namespace turf {

std_msgs::msg::dds_::Header_ CameraHeader(const CameraSpec& camera, int64_t sim_time_ns) {
  std_msgs::msg::dds_::Header_ h;
  h.stamp().sec(static_cast<int32_t>(sim_time_ns / 1'000'000'000));
  h.stamp().nanosec(static_cast<uint32_t>(sim_time_ns % 1'000'000'000));
  h.frame_id(CameraId(camera));
  return h;
}

sensor_msgs::msg::dds_::Image_ ImageMessage(const CameraSpec& camera, int64_t sim_time_ns, std::vector<uint8_t> bytes) {
  sensor_msgs::msg::dds_::Image_ m;
  m.header(CameraHeader(camera, sim_time_ns));
  m.height(static_cast<uint32_t>(camera.height));
  m.width(static_cast<uint32_t>(camera.width));
  m.encoding(RosEncoding(camera.encoding));
  m.is_bigendian(0);
  const uint32_t bytes_per_pixel = camera.encoding == ImageEncoding::kYuv422 ? 2 : 3;
  m.step(static_cast<uint32_t>(camera.width) * bytes_per_pixel);
  m.data(std::move(bytes));
  return m;
}

sensor_msgs::msg::dds_::CompressedImage_ CompressedMessage(const CameraSpec& camera, int64_t sim_time_ns,
                                                           std::vector<uint8_t> bytes) {
  sensor_msgs::msg::dds_::CompressedImage_ m;
  m.header(CameraHeader(camera, sim_time_ns));
  m.format("jpeg");
  m.data(std::move(bytes));
  return m;
}

sensor_msgs::msg::dds_::CameraInfo_ CameraInfoMessage(const CameraSpec& camera, int64_t sim_time_ns) {
  const Intrinsics k = IntrinsicsOf(camera.width, camera.height, camera.hfov);
  sensor_msgs::msg::dds_::CameraInfo_ m;
  m.header(CameraHeader(camera, sim_time_ns));
  m.height(static_cast<uint32_t>(camera.height));
  m.width(static_cast<uint32_t>(camera.width));
  m.distortion_model("plumb_bob");
  m.d({0, 0, 0, 0, 0});
  m.k({k.fx, 0, k.cx, 0, k.fy, k.cy, 0, 0, 1});
  m.r({1, 0, 0, 0, 1, 0, 0, 0, 1});
  m.p({k.fx, 0, k.cx, 0, 0, k.fy, k.cy, 0, 0, 0, 1, 0});
  m.binning_x(0);
  m.binning_y(0);
  return m;
}

}  // namespace turf
