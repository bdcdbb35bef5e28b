// DDS Security with a real turf-render (issue 19 with issue 16's cameras): turf-sim as `sim` and turf-render as
// `render` (identities of `turf security init`, lab profile). A team identity reads the images; a participant
// without security never does; turf-render given an identity that may not publish the camera topics refuses to start
// and names the topic.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <turf/idl/RosImagePubSubTypes.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "dds/camera_topics.h"
#include "dds/vendor_participant.h"
#include "participants/launcher/security_init.h"
#include "tests/support/process.h"
#include "tests/support/wake_wait.h"
#include "tests/test_domain.h"

namespace turf::test {
namespace {

namespace fs = std::filesystem;
namespace ros = sensor_msgs::msg::dds_;
using Clock = std::chrono::steady_clock;
using std::chrono::seconds;

class SecurityRender : public ::testing::Test {
 protected:
  void SetUp() override {
    const std::string test = ::testing::UnitTest::GetInstance()->current_test_info()->name();
    dir_ = LogDir() + "/security_render_" + std::to_string(getpid()) + "_" + test;
    fs::remove_all(dir_);
    launch::SecurityInitOptions o;
    o.dir = dir_;
    o.prefix = prefix_;
    const std::vector<std::string> errors = launch::InitSecurity(o);
    ASSERT_TRUE(errors.empty()) << errors.front();
    scene_ = dir_ + "/scene.yaml";
    std::ofstream(scene_) << "kind: legged\nname: security-render\nphysics: {step: 0.005}\n"
                             "rates: {joint_state_hz: 200}\nrobots:\n  - name: t1\n    model: " TURF_SOURCE_DIR
                             "/configs/robots/t1.xml\n    z: 0.665\n    cameras:\n"
                             "      - {name: camera, width: 64, height: 48, rate_hz: 20}\n";
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::vector<std::string> Args(const std::string& program, const std::string& identity) const {
    return {Built(program), "--scene", scene_,       "--domain",           std::to_string(domain_),
            "--prefix",     prefix_,   "--security", dir_ + "/" + identity};
  }
  std::string ImageTopic() const { return dds::CameraTopicName(prefix_, "t1", "camera", dds::CameraTopic::kImage); }

  const int domain_ = TestDomain(62);
  const std::string prefix_ = "secr" + std::to_string(getpid());
  std::string dir_;
  std::string scene_;
};

// A reader of the head camera's images on `participant`: counts them and wakes `wait`.
struct ImageCount {
  ImageCount(dds::VendorParticipant& participant, const std::string& topic, WakeWait* wait)
      : reader(participant.MakeReader<ros::Image_PubSubType>(topic, [this, wait](const ros::Image_& img, int64_t) {
          if (img.width() == 64 && img.height() == 48 && img.data().size() == 64u * 48u * 3u) ++images;
          wait->Wake();
        })) {}
  std::atomic<int> images{0};
  std::unique_ptr<dds::VendorParticipant::RawReader> reader;
};

TEST_F(SecurityRender, ATeamReadsTheRenderIdentitysImagesAndAnUnsecuredReaderNever) {
  WakeWait wait;
  dds::VendorParticipant unsecured(dds::VendorOptions{domain_, "test-unsecured", "", true});
  ImageCount stranger(unsecured, ImageTopic(), &wait);
  dds::VendorParticipant blue(dds::VendorOptions{domain_, "test-blue", dir_ + "/blue", true});
  ImageCount team(blue, ImageTopic(), &wait);
  auto render = std::make_unique<Process>("security_render", Args("participants/render/turf-render", "render"));
  Process sim("security_render_sim", Args("participants/sim/turf-sim", "sim"));
  // The positive marker first: the team's reader has images of the declared size (authenticated, decrypted).
  // Fast DDS 2.9's known limit (README, Access control): now and then one pair of participants never finishes
  // authenticating (1 run in 32 of this test on a quiet machine). As the README tells an operator, the process
  // is restarted once, and that is reported; a second stall fails the test.
  int restarted = 0;
  if (!wait.Until(Clock::now() + seconds(20), [&] { return team.images >= 5; })) {
    render->Stop();
    render = std::make_unique<Process>("security_render_restarted", Args("participants/render/turf-render", "render"));
    ++restarted;
    std::printf("turf-render restarted: no image after 20 s (a DDS authentication that never ended)\n");
  }
  RecordProperty("render_restarted", restarted);
  ASSERT_TRUE(wait.Until(Clock::now() + seconds(60), [&] { return team.images >= 5; }))
      << "team images " << team.images << "\nturf-render:\n"
      << render->Log() << "\nturf-sim:\n"
      << sim.Log();
  EXPECT_EQ(stranger.images, 0) << "a participant without security read a secured camera topic";
  // The team's participant watched its authentications (dds/authentication_watch.h): turf-render's ended.
  EXPECT_GE(blue.AuthenticationsNow().ended, 1u);
  EXPECT_EQ(sim.Stop(), 0);
  EXPECT_EQ(render->Stop(), 0);
}

TEST_F(SecurityRender, AnIdentityThatMayNotPublishCamerasMakesTurfRenderRefuseToStart) {
  Process render("security_render_as_blue", Args("participants/render/turf-render", "blue"));
  const std::optional<int> status = render.Wait(std::chrono::milliseconds(60000));
  ASSERT_TRUE(status) << "turf-render kept running as blue:\n" << render.Log();
  EXPECT_TRUE(WIFEXITED(*status) && WEXITSTATUS(*status) != 0) << render.Log();
  EXPECT_NE(render.Log().find("cannot create a DDS writer for " + ImageTopic()), std::string::npos) << render.Log();
}

}  // namespace
}  // namespace turf::test
