#include "participants/viewer/camera_frames.h"

#include <spdlog/spdlog.h>
#include <turf/idl/RosImagePubSubTypes.h>

#include <atomic>
#include <map>
#include <mutex>
#include <vector>

#include "codecs/image/image_codec.h"
#include "core/camera/camera_model.h"
#include "dds/camera_topics.h"
#include "dds/vendor_participant.h"
#include "participants/common/process.h"

namespace turf::viewer {

namespace {

namespace ros = sensor_msgs::msg::dds_;
constexpr size_t kMaxCompressed = 8u << 20;
constexpr int kJpegQuality = 80;

}  // namespace

struct CameraFrames::Impl {
  struct Frame {
    std::vector<uint8_t> raw;  // rgb8 or yuyv, rows packed
    bool yuyv = false;
    int width = 0, height = 0;
    std::string jpeg;  // empty until encoded (or a compressed frame's bytes)
  };
  struct Camera {
    bool followed = false;  // readers made or being made
    uint64_t asked = 0;     // when it was last asked for (a count of requests)
    std::unique_ptr<dds::VendorParticipant::RawReader> raw, compressed;
    std::optional<Frame> newest;
  };

  CameraFramesOptions options;
  // Readers are made under follow_mutex and never under `mutex`: the readers' callbacks take `mutex` on Fast DDS's
  // threads, and making a reader waits for Fast DDS's own locks (both under one lock deadlocked, once in a soak).
  std::mutex follow_mutex;
  std::unique_ptr<dds::VendorParticipant> participant;  // under follow_mutex
  std::mutex mutex;                                     // guards everything below
  std::map<std::string, Camera> cameras;
  uint64_t requests = 0;
  std::atomic<uint64_t> served{0};
  RejectLog rejects{"camera panel input"};

  void Refuse(const std::string& kind, const std::string& what) { rejects.Reject(kind, what); }

  // Drops a camera's readers outside `mutex` (their callbacks take it) and with no reader being made.
  void Drop(Camera camera) {
    std::lock_guard<std::mutex> follow(follow_mutex);
    camera.raw.reset();
    camera.compressed.reset();
  }

  // With `mutex` held: when kMaxCameras are followed, the one asked for least recently leaves the map (returned, to
  // be dropped once `mutex` is released).
  std::optional<Camera> MakeRoom() {
    size_t followed = 0;
    auto oldest = cameras.end();
    for (auto it = cameras.begin(); it != cameras.end(); ++it) {
      if (!it->second.followed) continue;
      ++followed;
      if (oldest == cameras.end() || it->second.asked < oldest->second.asked) oldest = it;
    }
    if (followed < kMaxCameras) return std::nullopt;
    spdlog::info("camera panel: no longer reading {} (asked for least recently; {} cameras at most)", oldest->first,
                 kMaxCameras);
    Camera out = std::move(oldest->second);
    cameras.erase(oldest);
    return out;
  }

  void OnRaw(const std::string& key, const ros::Image_& image) {
    const bool yuyv = image.encoding() == "yuv422_yuy2";
    const size_t bpp = yuyv ? 2 : 3;
    if ((!yuyv && image.encoding() != "rgb8") || image.width() == 0 || image.height() == 0 ||
        image.width() > kMaxImageSide || image.height() > kMaxImageSide || image.step() != image.width() * bpp ||
        image.data().size() != size_t{image.step()} * image.height())
      return Refuse("image", key + ": an image of " + std::to_string(image.width()) + "x" +
                                 std::to_string(image.height()) + " '" + image.encoding() + "'");
    Frame f{image.data(), yuyv, static_cast<int>(image.width()), static_cast<int>(image.height()), {}};
    std::lock_guard<std::mutex> lock(mutex);
    if (auto it = cameras.find(key); it != cameras.end()) it->second.newest = std::move(f);
  }

  void OnCompressed(const std::string& key, const ros::CompressedImage_& image) {
    if (image.format().find("jpeg") == std::string::npos || image.data().empty() ||
        image.data().size() > kMaxCompressed)
      return Refuse("compressed_image", key + ": a compressed image '" + image.format() + "'");
    Frame f;
    f.jpeg.assign(image.data().begin(), image.data().end());
    std::lock_guard<std::mutex> lock(mutex);
    if (auto it = cameras.find(key); it != cameras.end()) it->second.newest = std::move(f);
  }

  // The camera's readers, made at its first request (under follow_mutex, not `mutex`), then kept in its slot.
  void Follow(const CameraTarget& t, const std::string& key) {
    std::lock_guard<std::mutex> follow(follow_mutex);
    if (!participant)
      participant = std::make_unique<dds::VendorParticipant>(
          dds::VendorOptions{options.domain, options.name + "-cameras", options.security, /*large_samples=*/true});
    const std::string raw = dds::CameraTopicName(options.prefix, t.robot, t.camera, dds::CameraTopic::kImage);
    const std::string jpeg = dds::CameraTopicName(options.prefix, t.robot, t.camera, dds::CameraTopic::kCompressed);
    auto raw_reader = participant->MakeReader<ros::Image_PubSubType>(
        raw, [this, key](const ros::Image_& image, int64_t) { OnRaw(key, image); });
    auto compressed_reader = participant->MakeReader<ros::CompressedImage_PubSubType>(
        jpeg, [this, key](const ros::CompressedImage_& image, int64_t) { OnCompressed(key, image); });
    spdlog::info("camera panel: reading {} and {}", raw, jpeg);
    std::unique_lock<std::mutex> lock(mutex);
    const auto it = cameras.find(key);
    if (it == cameras.end() || !it->second.followed) {  // no longer followed meanwhile: the readers go
      lock.unlock();
      raw_reader.reset();
      compressed_reader.reset();
      return;
    }
    it->second.raw = std::move(raw_reader);
    it->second.compressed = std::move(compressed_reader);
  }
};

CameraFrames::CameraFrames(CameraFramesOptions options) : impl_(std::make_unique<Impl>()) {
  impl_->options = std::move(options);
}

CameraFrames::~CameraFrames() {
  std::lock_guard<std::mutex> follow(impl_->follow_mutex);  // no reader being made
  std::map<std::string, Impl::Camera> cameras;
  {
    std::lock_guard<std::mutex> lock(impl_->mutex);
    cameras.swap(impl_->cameras);
  }
  cameras.clear();  // the readers go (their callbacks end) before the participant
}

std::optional<std::string> CameraFrames::Jpeg(std::string_view target) {
  const std::optional<CameraTarget> t = ParseCameraTarget(target);
  if (!t) {
    impl_->Refuse("target", "target '" + std::string(target.substr(0, 80)) + "'");
    return std::nullopt;
  }
  const std::string key = t->robot + "/" + t->camera;
  std::unique_lock<std::mutex> lock(impl_->mutex);
  auto it = impl_->cameras.find(key);
  if (it == impl_->cameras.end() || !it->second.followed) {
    std::optional<Impl::Camera> evicted = impl_->MakeRoom();
    Impl::Camera& c = impl_->cameras[key];
    c.followed = true;
    c.asked = ++impl_->requests;
    lock.unlock();
    if (evicted) impl_->Drop(std::move(*evicted));
    impl_->Follow(*t, key);
    return std::nullopt;
  }
  it->second.asked = ++impl_->requests;
  std::optional<Impl::Frame>& f = it->second.newest;
  if (!f) return std::nullopt;
  if (f->jpeg.empty()) {
    std::vector<uint8_t> rgb = f->raw;
    if (f->yuyv) rgb = image::YuyvToRgb(f->raw, f->width, f->height).bytes;
    const image::Encoded e = image::EncodeJpeg(rgb, f->width, f->height, kJpegQuality);
    if (e.error != Error::kOk) {
      impl_->Refuse("jpeg", key + ": a frame JPEG refused (" + std::string(ErrorName(e.error)) + ")");
      f.reset();
      return std::nullopt;
    }
    f->jpeg.assign(e.bytes.begin(), e.bytes.end());
    f->raw.clear();
  }
  ++impl_->served;
  return f->jpeg;
}

uint64_t CameraFrames::refused() const { return impl_->rejects.Total(); }
uint64_t CameraFrames::served() const { return impl_->served.load(); }

}  // namespace turf::viewer
