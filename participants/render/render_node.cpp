#include "participants/render/render_node.h"

#include <spdlog/spdlog.h>
#include <turf/idl/CameraControlPubSubTypes.h>
#include <turf/idl/JointsPubSubTypes.h>
#include <turf/idl/RosImagePubSubTypes.h>

#include <chrono>
#include <cmath>
#include <mutex>
#include <stdexcept>

#include "codecs/image/image_codec.h"
#include "dds/bus.h"
#include "dds/camera_topics.h"
#include "dds/participant.h"
#include "dds/vendor_participant.h"
#include "participants/common/process.h"
#include "participants/common/stalled_authentication.h"
#include "participants/common/wakeup.h"
#include "participants/render/camera_messages.h"
#include "participants/render/camera_switch.h"
#include "participants/render/egl_context.h"
#include "participants/render/scene_renderer.h"

namespace turf {

namespace ros = sensor_msgs::msg::dds_;
using Clock = std::chrono::steady_clock;

std::vector<CameraSpec> SelectCameras(const std::vector<CameraSpec>& all, const std::vector<std::string>& requested) {
  std::vector<CameraSpec> out;
  std::string known;
  for (const CameraSpec& c : all) known += (known.empty() ? "" : ", ") + CameraId(c);
  for (const std::string& id : requested) {
    bool found = false;
    for (const CameraSpec& c : all) found = found || CameraId(c) == id;
    if (!found)
      throw std::invalid_argument("--cameras: no camera '" + id +
                                  "' in the scene (its cameras: " + (known.empty() ? "none" : known) + ")");
  }
  for (const CameraSpec& c : all) {
    bool wanted = requested.empty() ? c.enabled : false;
    for (const std::string& id : requested) wanted = wanted || CameraId(c) == id;
    if (wanted) out.push_back(c);
  }
  return out;
}

std::vector<CameraSpec> RenderSet(const std::vector<CameraSpec>& all, const std::vector<std::string>& requested,
                                  bool off) {
  std::vector<CameraSpec> out = requested.empty() ? all : SelectCameras(all, requested);
  for (CameraSpec& c : out) c.enabled = !off && (requested.empty() ? c.enabled : true);
  return out;
}

namespace {

bool Finite(const idl::Vec3& v) { return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z()); }
bool Finite(const idl::Quat& q) {
  return std::isfinite(q.w()) && std::isfinite(q.x()) && std::isfinite(q.y()) && std::isfinite(q.z());
}

// One camera's publishing end: an image (or compressed image) writer and a camera_info writer.
struct CameraOutput {
  CameraSpec spec;
  FrameSchedule schedule;
  uint64_t dropped_before = 0;  // by the schedules this camera had before its last switch
  std::unique_ptr<dds::VendorParticipant::Writer<ros::Image_PubSubType>> image;
  std::unique_ptr<dds::VendorParticipant::Writer<ros::CompressedImage_PubSubType>> compressed;
  std::unique_ptr<dds::VendorParticipant::Writer<ros::CameraInfo_PubSubType>> info;
};

}  // namespace

class RenderNode::Impl {
 public:
  Impl(RenderOptions options, LeggedScene scene, std::vector<CameraSpec> cameras)
      : options_(std::move(options)), scene_(std::move(scene)), cameras_(std::move(cameras)), switch_(cameras_) {}

  void Run(const std::function<bool()>& stop) {
    EglContext egl;
    spdlog::info("OpenGL: {}", egl.Renderer());
    SceneRenderer renderer(scene_, cameras_, RenderLook{options_.team_colours, options_.brightness});
    spdlog::info("look: team colours {} (robots named red_*, blue_*, yellow_*), lights x{}",
                 options_.team_colours ? "on" : "off", options_.brightness);
    dds::VendorParticipant images(dds::VendorOptions{options_.domain, options_.name + "-images", options_.security,
                                                     true, options_.authentication_timeout()});
    std::vector<CameraOutput> outputs = MakeOutputs(images);
    {
      std::lock_guard<std::mutex> lock(stats_mutex_);
      stats_.cameras_on = switch_.enabled_count();
    }
    Wakeup wake;
    auto controls = images.MakeReader<idl::CameraControlPubSubType>(
        dds::CameraControlTopicName(options_.prefix), [this, &wake](const idl::CameraControl& c, int64_t) {
          std::lock_guard<std::mutex> lock(controls_mutex_);
          controls_.push_back({c.robot(), c.camera(), c.enabled(), c.rate_hz(), c.source()});
          wake.Notify();
        });
    spdlog::info("reads {} (turf::idl::CameraControl): cameras on and off at run time; {} of {} on",
                 dds::CameraControlTopicName(options_.prefix), switch_.enabled_count(), switch_.size());
    dds::Participant turf(DdsOptions(options_));
    auto reader = turf.MakeReader(dds::Topic::kRobotsState, [&wake] { wake.Notify(); });
    spdlog::info("{}", dds::EndpointLine(options_.prefix, dds::Topic::kRobotsState, dds::Endpoint::kReader));
    std::vector<idl::LeggedState> batch;
    auto next_status = Clock::now() + Seconds(options_.status_every);
    bool have_sim = false;  // turf-sim's states have come
    StalledAuthenticationRestart restart;
    spdlog::info("waiting for turf-sim on {}", turf.Describe());
    while (!stop()) {
      wake.WaitFor(std::chrono::milliseconds(100));
      ApplyControls(outputs);
      if (reader->Take(&batch)) {
        if (!have_sim) spdlog::info("receiving turf-sim's robot states");
        have_sim = true;
        Handle(batch, renderer, outputs);
      }
      if (restart.Check(turf.AuthenticationsNow(), !have_sim)) break;
      if (Clock::now() >= next_status) {
        LogStatus();
        next_status = Clock::now() + Seconds(options_.status_every);
      }
    }
    LogStatus();
    controls.reset();  // no callback into this object from here on
  }

  RenderStats Stats() const {
    std::lock_guard<std::mutex> lock(stats_mutex_);
    return stats_;
  }

 private:
  static Clock::duration Seconds(double s) {
    return std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(s));
  }

  std::vector<CameraOutput> MakeOutputs(dds::VendorParticipant& images) {
    std::vector<CameraOutput> outputs;
    for (const CameraSpec& c : cameras_) {
      CameraOutput o{c, FrameSchedule(c.rate_hz), 0, nullptr, nullptr, nullptr};
      const bool jpeg = c.encoding == ImageEncoding::kJpeg;
      const dds::CameraTopic kind = jpeg ? dds::CameraTopic::kCompressed : dds::CameraTopic::kImage;
      const std::string image_topic = dds::CameraTopicName(options_.prefix, c.robot, c.name, kind);
      const std::string info_topic =
          dds::CameraTopicName(options_.prefix, c.robot, c.name, dds::CameraTopic::kCameraInfo);
      if (jpeg)
        o.compressed = images.MakeWriter<ros::CompressedImage_PubSubType>(image_topic);
      else
        o.image = images.MakeWriter<ros::Image_PubSubType>(image_topic);
      o.info = images.MakeWriter<ros::CameraInfo_PubSubType>(info_topic);
      spdlog::info("camera {}: {}x{}, {:.1f} deg horizontal, {} Hz of sim time, {}: writes {} ({}) and {} ({}); {}; {}",
                   CameraId(c), c.width, c.height, c.hfov * 180.0 / M_PI, c.rate_hz, EncodingName(c.encoding),
                   image_topic, dds::Info(kind).dds_type, info_topic, dds::Info(dds::CameraTopic::kCameraInfo).dds_type,
                   dds::kCameraTopicQos, c.enabled ? "on" : "off");
      outputs.push_back(std::move(o));
    }
    return outputs;
  }

  // Renders the newest state of `batch` for every camera due at its time.
  void Handle(const std::vector<idl::LeggedState>& batch, SceneRenderer& renderer, std::vector<CameraOutput>& outs) {
    const idl::LeggedState& state = batch.back();
    {
      std::lock_guard<std::mutex> lock(stats_mutex_);
      stats_.states += batch.size();
      stats_.states_superseded += batch.size() - 1;
    }
    std::vector<size_t> due;
    for (size_t i = 0; i < outs.size(); ++i)
      if (switch_.enabled(i) && outs[i].schedule.Offer(state.sim_time_ns())) due.push_back(i);
    if (due.empty()) return UpdateDropped(outs);
    if (!Apply(state, renderer)) {
      std::lock_guard<std::mutex> lock(stats_mutex_);
      ++stats_.states_refused;
      return;
    }
    const auto start = Clock::now();
    for (size_t i : due) Publish(outs[i], i, state.sim_time_ns(), renderer);
    std::lock_guard<std::mutex> lock(stats_mutex_);
    stats_.render_seconds += std::chrono::duration<double>(Clock::now() - start).count();
    stats_.frames += due.size();
    UpdateDroppedLocked(outs);
  }

  void UpdateDropped(const std::vector<CameraOutput>& outs) {
    std::lock_guard<std::mutex> lock(stats_mutex_);
    UpdateDroppedLocked(outs);
  }
  void UpdateDroppedLocked(const std::vector<CameraOutput>& outs) {
    stats_.dropped = 0;
    for (const CameraOutput& o : outs) stats_.dropped += o.dropped_before + o.schedule.dropped();
  }

  // The control samples that arrived, in order: a camera switched on starts a new schedule at its rate.
  void ApplyControls(std::vector<CameraOutput>& outs) {
    std::vector<CameraControlRequest> pending;
    {
      std::lock_guard<std::mutex> lock(controls_mutex_);
      pending.swap(controls_);
    }
    for (const CameraControlRequest& r : pending) {
      std::string why;
      const CameraSwitch::Outcome outcome = switch_.Apply(r, &why);
      std::lock_guard<std::mutex> lock(stats_mutex_);
      if (outcome == CameraSwitch::Outcome::kRefused) {
        ++stats_.controls_refused;
        if (stats_.controls_refused <= 5 || stats_.controls_refused % 100 == 0)
          spdlog::warn("camera control for {}/{} from '{}' refused ({} so far): {}", Printable(Clipped(r.robot)),
                       Printable(Clipped(r.camera)), Printable(Clipped(r.source)), stats_.controls_refused, why);
        continue;
      }
      if (outcome != CameraSwitch::Outcome::kChanged) continue;
      ++stats_.controls;
      const size_t i = switch_.Find(r.robot, r.camera);
      CameraOutput& o = outs[i];
      o.dropped_before += o.schedule.dropped();
      o.schedule = FrameSchedule(switch_.rate_hz(i));
      // A sender may switch a camera on and off in every sample: at most a line a second per kind.
      switches_.Reject(
          r.enabled ? "on" : "off",
          fmt::format("camera {} {}{} (asked by '{}')", CameraId(o.spec), r.enabled ? "on" : "off",
                      r.enabled ? fmt::format(" at {} Hz of sim time", switch_.rate_hz(i)) : "", Clipped(r.source)));
    }
    std::lock_guard<std::mutex> lock(stats_mutex_);
    stats_.cameras_on = switch_.enabled_count();
  }

  // The state's poses into the renderer; false (nothing drawn) if a value is not finite.
  bool Apply(const idl::LeggedState& state, SceneRenderer& renderer) {
    for (const idl::LinkState& robot : state.links())
      for (const idl::LinkPose& link : robot.links())
        if (!Finite(link.position()) || !Finite(link.orientation())) return false;
    if (state.has_ball() && !Finite(state.ball_position())) return false;
    for (const idl::LinkState& robot : state.links()) {
      for (const idl::LinkPose& link : robot.links()) {
        const auto& p = link.position();
        const auto& q = link.orientation();
        if (!renderer.SetBodyPose(robot.robot(), link.name(),
                                  Pose{{p.x(), p.y(), p.z()}, {q.w(), q.x(), q.y(), q.z()}}))
          WarnUnknown(robot.robot() + "/" + link.name());
      }
    }
    if (state.has_ball()) {
      const auto& b = state.ball_position();
      renderer.SetBallPosition({b.x(), b.y(), b.z()});
    }
    renderer.UpdateFrames();
    return true;
  }

  void WarnUnknown(const std::string& body) {
    if (unknown_warned_++ < 5)
      spdlog::warn("robots/state names body {}, which this scene lacks (another scene?)", body);
  }

  void Publish(CameraOutput& out, size_t index, int64_t sim_time_ns, SceneRenderer& renderer) {
    const CameraSpec& c = out.spec;
    renderer.Render(index, &rgb_);
    AddPixelNoise(&rgb_, c.noise_stddev, scene_.seed, c, sim_time_ns);
    image::Encoded encoded;
    switch (c.encoding) {
      case ImageEncoding::kRgb8:
        encoded.bytes = rgb_;
        break;
      case ImageEncoding::kYuv422:
        encoded = image::RgbToYuyv(rgb_, c.width, c.height);
        break;
      case ImageEncoding::kJpeg:
        encoded = image::EncodeJpeg(rgb_, c.width, c.height, c.jpeg_quality);
        break;
    }
    if (encoded.error != Error::kOk) {
      std::lock_guard<std::mutex> lock(stats_mutex_);
      ++stats_.encode_errors;
      return;
    }
    if (out.compressed)
      out.compressed->Write(CompressedMessage(c, sim_time_ns, std::move(encoded.bytes)));
    else
      out.image->Write(ImageMessage(c, sim_time_ns, std::move(encoded.bytes)));
    out.info->Write(CameraInfoMessage(c, sim_time_ns));
  }

  void LogStatus() {
    const RenderStats s = Stats();
    const double fps = s.render_seconds > 0 ? static_cast<double>(s.frames) / s.render_seconds : 0.0;
    spdlog::info(
        "status: {} frames rendered, {} dropped (due by sim time while busy or between states), {} states taken "
        "({} superseded, {} refused), {} encode errors; {:.1f} frames per second of render time; {} camera(s) on, "
        "{} switches, {} controls refused",
        s.frames, s.dropped, s.states, s.states_superseded, s.states_refused, s.encode_errors, fps, s.cameras_on,
        s.controls, s.controls_refused);
    spdlog::default_logger()->flush();  // at once, also where the output goes to a file or pipe
  }

  RenderOptions options_;
  LeggedScene scene_;
  std::vector<CameraSpec> cameras_;
  CameraSwitch switch_;  // the render thread's only
  std::mutex controls_mutex_;
  std::vector<CameraControlRequest> controls_;  // arrived, not applied yet
  std::vector<uint8_t> rgb_;
  int unknown_warned_ = 0;
  mutable std::mutex stats_mutex_;
  RenderStats stats_;
  RejectLog switches_{"camera switched", std::chrono::seconds(1), LogLine::kEvent};
};

RenderNode::RenderNode(RenderOptions options, LeggedScene scene, std::vector<CameraSpec> cameras)
    : impl_(std::make_unique<Impl>(std::move(options), std::move(scene), std::move(cameras))) {}
RenderNode::~RenderNode() = default;
void RenderNode::Run(const std::function<bool()>& stop) { impl_->Run(stop); }
RenderStats RenderNode::Stats() const { return impl_->Stats(); }

}  // namespace turf
