// The viewer's camera panel: GET /camera/<robot>/<camera>.jpg serves the newest image a camera topic carried (an
// rgb8 image_raw encoded to JPEG; a compressed one as it came), 404 until one has come; targets that are no camera
// are refused. The images come from this test's own writer, as turf-render writes them (no renderer needed).
#include <gtest/gtest.h>
#include <turf/idl/RosImagePubSubTypes.h>

#include <thread>

#include "codecs/image/image_codec.h"
#include "dds/camera_topics.h"
#include "dds/vendor_participant.h"
#include "participants/viewer/camera_frames.h"
#include "participants/viewer/viewer_node.h"
#include "tests/sim/sim_harness.h"
#include "tests/support/in_process.h"
#include "tests/viewer/viewer_under_test.h"
#include "tests/viewer/web_client.h"

namespace turf::test {
namespace {

namespace ros = sensor_msgs::msg::dds_;

TEST(CameraTarget, OnlyCameraJpegTargetsOfTokens) {
  const auto t = viewer::ParseCameraTarget("/camera/red_1/camera.jpg?n=123");
  ASSERT_TRUE(t.has_value());
  EXPECT_EQ(t->robot, "red_1");
  EXPECT_EQ(t->camera, "camera");
  for (const char* bad : {"/camera/red_1.jpg", "/camera/a/b/c.jpg", "/camera/../x.jpg", "/camera/a/b.png",
                          "/camera//b.jpg", "/camera/a/.jpg", "/camera/a-b/c.jpg", "/cameras/a/b.jpg", ""})
    EXPECT_FALSE(viewer::ParseCameraTarget(bad).has_value()) << bad;
  EXPECT_FALSE(viewer::ParseCameraTarget("/camera/" + std::string(65, 'a') + "/c.jpg").has_value());
}

// An 8 x 4 rgb8 image: red on the left half, blue on the right.
ros::Image_ TestImage() {
  ros::Image_ image;
  image.width(8);
  image.height(4);
  image.encoding("rgb8");
  image.step(24);
  std::vector<uint8_t> data;
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 8; ++x) {
      const bool left = x < 4;
      data.insert(data.end(), {static_cast<uint8_t>(left ? 230 : 10), 10, static_cast<uint8_t>(left ? 10 : 230)});
    }
  image.data(data);
  return image;
}

// GETs `target` every 100 ms (each GET keeps the viewer subscribed; images come from `write`, called before each)
// until it answers 200 or 30 s pass.
HttpResult GetWhenThere(int port, const std::string& target, const std::function<void()>& write) {
  HttpResult r;
  const auto end = Clock::now() + 30s;
  do {
    write();
    r = HttpGet(port, target);
    if (r.status == 200) break;
    std::this_thread::sleep_for(100ms);
  } while (Clock::now() < end);
  return r;
}

TEST(CameraPanel, ServesTheNewestImageAsJpeg) {
  const dds::ParticipantOptions dds = UniqueDds("viewer-camera");
  ViewerUnderTest viewer(dds);
  dds::VendorParticipant images(dds::VendorOptions{dds.domain, "camera-panel-test", "", true});
  auto raw = images.MakeWriter<ros::Image_PubSubType>(
      dds::CameraTopicName(dds.prefix, "t1", "camera", dds::CameraTopic::kImage));
  auto compressed = images.MakeWriter<ros::CompressedImage_PubSubType>(
      dds::CameraTopicName(dds.prefix, "t1", "eye", dds::CameraTopic::kCompressed));
  EXPECT_EQ(HttpGet(viewer.port(), "/camera/t1/camera.jpg").status, 404) << "nothing has come yet";

  const HttpResult r = GetWhenThere(viewer.port(), "/camera/t1/camera.jpg", [&] { raw->Write(TestImage()); });
  ASSERT_EQ(r.status, 200) << r.error;
  EXPECT_EQ(r.content_type, "image/jpeg");
  int w = 0, h = 0;
  const image::Encoded rgb = image::DecodeJpeg(std::vector<uint8_t>(r.body.begin(), r.body.end()), 1000, &w, &h);
  ASSERT_EQ(rgb.error, Error::kOk);
  ASSERT_EQ(w, 8);
  ASSERT_EQ(h, 4);
  const uint8_t* left = &rgb.bytes[3 * (8 + 1)];
  const uint8_t* right = &rgb.bytes[3 * (8 + 6)];
  EXPECT_GT(left[0], 150);
  EXPECT_LT(left[2], 90);
  EXPECT_GT(right[2], 150);
  EXPECT_LT(right[0], 90);

  ros::CompressedImage_ jpeg;
  jpeg.format("jpeg");
  const std::vector<uint8_t> bytes(r.body.begin(), r.body.end());
  jpeg.data(bytes);
  const HttpResult c = GetWhenThere(viewer.port(), "/camera/t1/eye.jpg", [&] { compressed->Write(jpeg); });
  ASSERT_EQ(c.status, 200) << c.error;
  EXPECT_EQ(c.body, r.body) << "a compressed image as it came";

  EXPECT_EQ(HttpGet(viewer.port(), "/camera/t1/../x.jpg").status, 404);
  EXPECT_EQ(HttpGet(viewer.port(), "/camera/t1.jpg").status, 404);
}

TEST(CameraPanel, BadImagesAreDroppedAndCounted) {
  const dds::ParticipantOptions dds = UniqueDds("viewer-camera-bad");
  viewer::CameraFrames frames(viewer::CameraFramesOptions{dds.domain, dds.prefix, "", "camera-frames-test"});
  dds::VendorParticipant images(dds::VendorOptions{dds.domain, "camera-panel-test", "", true});
  auto raw = images.MakeWriter<ros::Image_PubSubType>(
      dds::CameraTopicName(dds.prefix, "t1", "camera", dds::CameraTopic::kImage));
  EXPECT_FALSE(frames.Jpeg("/camera/t1/camera.jpg").has_value());  // subscribes
  ros::Image_ short_data = TestImage();
  short_data.data().resize(10);
  const auto end = Clock::now() + 30s;
  while (frames.refused() == 0 && Clock::now() < end) {
    raw->Write(short_data);
    std::this_thread::sleep_for(100ms);
  }
  EXPECT_GE(frames.refused(), 1u);
  EXPECT_FALSE(frames.Jpeg("/camera/t1/camera.jpg").has_value()) << "nothing kept of a bad image";
  const uint64_t before = frames.refused();
  EXPECT_FALSE(frames.Jpeg("/camera/x y/camera.jpg").has_value());
  EXPECT_EQ(frames.refused(), before + 1);
}

// Names that are no camera cannot use up the slots for good: past kMaxCameras, the camera asked for least recently
// is no longer followed, and a real camera asked for afterwards is served.
TEST(CameraPanel, ManyBogusCamerasDoNotLockOutARealOne) {
  const dds::ParticipantOptions dds = UniqueDds("viewer-camera-slots");
  viewer::CameraFrames frames(viewer::CameraFramesOptions{dds.domain, dds.prefix, "", "camera-frames-test"});
  for (size_t i = 0; i < 2 * viewer::CameraFrames::kMaxCameras; ++i)
    EXPECT_FALSE(frames.Jpeg("/camera/bogus" + std::to_string(i) + "/cam.jpg").has_value());
  EXPECT_EQ(frames.refused(), 0u) << "following another camera is no refusal";
  dds::VendorParticipant images(dds::VendorOptions{dds.domain, "camera-panel-test", "", true});
  auto raw = images.MakeWriter<ros::Image_PubSubType>(
      dds::CameraTopicName(dds.prefix, "t1", "camera", dds::CameraTopic::kImage));
  std::optional<std::string> jpeg;
  const auto end = Clock::now() + 30s;
  while (!jpeg && Clock::now() < end) {
    raw->Write(TestImage());
    jpeg = frames.Jpeg("/camera/t1/camera.jpg");
    if (!jpeg) std::this_thread::sleep_for(100ms);  // polling, as the page does
  }
  ASSERT_TRUE(jpeg.has_value()) << "the real camera was locked out";
  EXPECT_FALSE(jpeg->empty());
  EXPECT_EQ(frames.served(), 1u);
}

}  // namespace
}  // namespace turf::test
