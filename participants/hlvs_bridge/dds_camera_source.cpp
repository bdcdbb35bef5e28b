#include "participants/hlvs_bridge/dds_camera_source.h"

#include <spdlog/spdlog.h>
#include <turf/idl/CameraControlPubSubTypes.h>
#include <turf/idl/RosImagePubSubTypes.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <map>
#include <mutex>
#include <thread>
#include <vector>

#include "dds/camera_topics.h"
#include "dds/vendor_participant.h"
#include "participants/common/process.h"
#include "participants/hlvs_bridge/camera_feed.h"

namespace turf {

namespace {

namespace ros = sensor_msgs::msg::dds_;
using ControlWriter = dds::VendorParticipant::Writer<idl::CameraControlPubSubType>;

std::string Key(const std::string& robot, const std::string& camera) { return robot + "/" + camera; }

int64_t StampNs(const std_msgs::msg::dds_::Header_& h) {
  return static_cast<int64_t>(h.stamp().sec()) * 1'000'000'000 + h.stamp().nanosec();
}

}  // namespace

struct DdsCameraSource::Impl {
  struct Wanted {
    std::string robot, camera;
    uint32_t period_ms = 0;  // 0: off
  };

  CameraSourceOptions options;
  dds::VendorParticipant participant;  // images: large samples
  // The switch on a participant of its own, without large samples: written synchronously, so the last "off" is
  // sent before the bridge exits.
  dds::VendorParticipant control_participant;
  std::unique_ptr<ControlWriter> control;
  std::map<std::string, std::unique_ptr<dds::VendorParticipant::RawReader>> readers;  // bridge thread only
  int64_t base_ns = 0;                                                                // bridge thread only

  mutable std::mutex mutex;  // guards what follows
  CameraFeed feed;
  int64_t now_ns = 0;  // the newest simulation time the bridge asked for (frames stamped far past it are refused)
  std::map<std::string, Wanted> wanted;
  CameraSourceStats stats;
  bool stopping = false;
  std::condition_variable stop_cv;
  std::thread resend;  // re-sends the settings every kCameraControlResendSeconds

  explicit Impl(CameraSourceOptions o)
      : options(std::move(o)),
        participant(
            dds::VendorOptions{options.domain, options.name + "-cameras", options.security, /*large_samples=*/true}),
        control_participant(dds::VendorOptions{options.domain, options.name + "-camera-switch", options.security,
                                               /*large_samples=*/false}) {
    control = control_participant.MakeWriter<idl::CameraControlPubSubType>(dds::CameraControlTopicName(options.prefix));
    resend = std::thread([this] { ResendLoop(); });
  }

  ~Impl() {
    {
      std::lock_guard<std::mutex> lock(mutex);
      stopping = true;
    }
    stop_cv.notify_all();
    resend.join();
    for (auto& [key, w] : wanted)
      if (w.period_ms > 0) Write({w.robot, w.camera, 0});
    readers.clear();
  }

  void Write(const Wanted& w) {
    idl::CameraControl c;
    c.robot(w.robot);
    c.camera(w.camera);
    c.enabled(w.period_ms > 0);
    c.rate_hz(w.period_ms > 0 ? 1000.0 / w.period_ms : 0.0);
    c.source(options.name);
    control->Write(c);
    ++written;
  }

  void ResendLoop() {
    std::unique_lock<std::mutex> lock(mutex);
    const auto every = std::chrono::duration<double>(dds::kCameraControlResendSeconds);
    while (!stop_cv.wait_for(lock, every, [this] { return stopping; })) {
      std::vector<Wanted> on;
      for (const auto& [key, w] : wanted)
        if (w.period_ms > 0) on.push_back(w);
      lock.unlock();
      for (const Wanted& w : on) Write(w);
      lock.lock();
    }
  }

  void Subscribe(const std::string& robot, const std::string& camera) {
    const std::string key = Key(robot, camera);
    if (readers.count(key) != 0) return;
    const std::string topic = dds::CameraTopicName(options.prefix, robot, camera, dds::CameraTopic::kImage);
    readers[key] = participant.MakeReader<ros::Image_PubSubType>(
        topic, [this, key](const ros::Image_& image, int64_t) { OnImage(key, image); });
    spdlog::info("camera {}: reading {} (sensor_msgs::msg::dds_::Image_, {})", key, topic, dds::kCameraTopicQos);
  }

  // On Fast DDS's thread: converted here, so the bridge's step only moves the frame out.
  void OnImage(const std::string& key, const ros::Image_& image) {
    FeedFrame frame;
    const Error e = ToFeedFrame(StampNs(image.header()), image.width(), image.height(), image.encoding(), image.step(),
                                image.data(), &frame);
    std::lock_guard<std::mutex> lock(mutex);
    const int64_t stamp_ns = frame.stamp_ns;
    const Error put = e == Error::kOk ? feed.Put(key, std::move(frame), now_ns) : e;
    if (put != Error::kOk) {
      if (stats.refused++ < 5)
        spdlog::warn("camera {}: image refused ({}: {}x{}, '{}', step {}, {} bytes, stamped {} ns, time {} ns)", key,
                     ErrorName(put), image.width(), image.height(), image.encoding(), image.step(), image.data().size(),
                     stamp_ns, now_ns);
      return;
    }
    ++stats.frames;
  }

  std::atomic<uint64_t> written{0};  // control samples, from both threads
  RejectLog switches{"camera switched for HLVS clients", std::chrono::seconds(1), LogLine::kEvent};
};

DdsCameraSource::DdsCameraSource(CameraSourceOptions options) : impl_(std::make_unique<Impl>(std::move(options))) {
  spdlog::info("camera images: from turf-render's {} topics; switches cameras on {} as clients enable them",
               dds::CameraTopicPattern(impl_->options.prefix, dds::CameraTopic::kImage),
               dds::CameraControlTopicName(impl_->options.prefix));
}

DdsCameraSource::~DdsCameraSource() {
  const CameraSourceStats s = Stats();
  spdlog::info("camera images: {} frames received ({} refused), {} sent to clients, {} due with no new frame", s.frames,
               s.refused, s.sent, s.missed);
}

void DdsCameraSource::Attached(int64_t sim_time_ns) {
  impl_->base_ns = sim_time_ns;
  std::lock_guard<std::mutex> lock(impl_->mutex);
  impl_->now_ns = sim_time_ns;
}

void DdsCameraSource::Enable(const std::string& robot, const std::string& camera, uint32_t period_ms) {
  if (period_ms > 0) impl_->Subscribe(robot, camera);
  {
    std::lock_guard<std::mutex> lock(impl_->mutex);
    impl_->wanted[Key(robot, camera)] = {robot, camera, period_ms};
  }
  impl_->Write({robot, camera, period_ms});
  // A client may switch a camera every step: at most a line a second per kind.
  impl_->switches.Reject(period_ms > 0 ? "asked" : "switched_off",
                         period_ms > 0 ? fmt::format("{} every {} ms of simulated time", Key(robot, camera), period_ms)
                                       : Key(robot, camera));
}

std::optional<hlvs::CameraImage> DdsCameraSource::Take(const hlvs::CameraRequest& request) {
  const int64_t up_to = impl_->base_ns + static_cast<int64_t>(request.sim_time_ms) * 1'000'000;
  std::optional<FeedFrame> frame;
  {
    std::lock_guard<std::mutex> lock(impl_->mutex);
    impl_->now_ns = std::max(impl_->now_ns, up_to);
    frame = impl_->feed.Take(Key(request.robot, request.camera), up_to);
    ++(frame ? impl_->stats.sent : impl_->stats.missed);
  }
  if (!frame) return std::nullopt;
  hlvs::CameraImage image;
  image.width = frame->width;
  image.height = frame->height;
  image.image = std::move(frame->bgr);
  return image;
}

CameraSourceStats DdsCameraSource::Stats() const {
  CameraSourceStats s;
  {
    std::lock_guard<std::mutex> lock(impl_->mutex);
    s = impl_->stats;
  }
  s.controls = impl_->written.load();
  return s;
}

}  // namespace turf
