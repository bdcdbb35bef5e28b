// libFuzzer target for the SSL-Vision codec. The codec only encodes, so the
// untrusted input is the DDS samples: an SslField, a CameraFrame and a
// WorldState are built from the fuzz bytes (any double, NaN and infinities
// included; any ids, enums, counts and times). Whatever the checks accept must
// encode to bytes the generated proto parses back, complete and with only
// finite numbers; nothing may crash.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>

#include "codecs/proto/ssl_vision.pb.h"
#include "codecs/ssl_vision/detection.h"
#include "codecs/ssl_vision/geometry.h"
#include "codecs/ssl_vision/timestamps.h"
#include "codecs/ssl_vision/tracked.h"

namespace {

using namespace turf;

// Reads values from the fuzz bytes; zeros once they run out.
class Bytes {
 public:
  Bytes(const uint8_t* data, size_t size) : data_(data), size_(size) {}
  template <class T>
  T Get() {
    T v{};
    const size_t n = std::min(sizeof(T), size_ - pos_);
    std::memcpy(&v, data_ + pos_, n);
    pos_ += n;
    return v;
  }
  // Mostly plausible numbers, sometimes raw bit patterns (NaN, inf, huge).
  double Number() {
    const uint8_t kind = Get<uint8_t>();
    if (kind < 200) return static_cast<double>(Get<int16_t>()) / 1000.0;
    return Get<double>();
  }
  idl::Vec3 Vec3() {
    idl::Vec3 v;
    v.x(Number());
    v.y(Number());
    v.z(Number());
    return v;
  }

 private:
  const uint8_t* data_;
  size_t size_;
  size_t pos_ = 0;
};

void Require(bool ok) {
  if (!ok) std::abort();
}

template <class Packet>
void RequireParses(const std::vector<uint8_t>& bytes, Packet* out) {
  Require(out->ParseFromArray(bytes.data(), static_cast<int>(bytes.size())));
  Require(out->IsInitialized());
}

bool Finite(float v) { return std::isfinite(v); }

idl::SslField MakeField(Bytes& in) {
  idl::SslField f;
  f.division(in.Get<uint8_t>());
  f.field_length(in.Number());
  f.field_width(in.Number());
  f.boundary_width(in.Number());
  f.boundary_width_goal_line(in.Number());
  f.goal_width(in.Number());
  f.goal_depth(in.Number());
  f.goal_height(in.Number());
  f.penalty_area_depth(in.Number());
  f.penalty_area_width(in.Number());
  f.center_circle_radius(in.Number());
  f.line_thickness(in.Number());
  f.goal_center_to_penalty_mark(in.Number());
  f.ball_radius(in.Number());
  f.max_robot_radius(in.Number());
  f.ball_acc_slide(in.Number());
  f.ball_acc_roll(in.Number());
  f.ball_k_switch(in.Number());
  f.chip_damping_xy_first_hop(in.Number());
  f.chip_damping_xy_other_hops(in.Number());
  f.chip_damping_z(in.Number());
  const int cameras = in.Get<uint8_t>() % 8;
  for (int i = 0; i < cameras; ++i) {
    idl::CameraInfo c;
    c.id(in.Get<uint32_t>());
    c.position(in.Vec3());
    c.focal_length(in.Number() * 1000.0);
    c.image_width(in.Get<uint16_t>());
    c.image_height(in.Get<uint16_t>());
    f.cameras().push_back(c);
  }
  return f;
}

idl::CameraFrame MakeFrame(Bytes& in) {
  idl::CameraFrame f;
  f.camera_id(in.Get<uint8_t>() % 8);
  f.frame_number(in.Get<uint64_t>());
  f.capture_time_ns(in.Get<int64_t>());
  f.sent_time_ns(in.Get<int64_t>());
  const int balls = in.Get<uint8_t>() % 4;
  for (int i = 0; i < balls; ++i) {
    idl::DetectedBall b;
    b.position(in.Vec3());
    b.confidence(static_cast<float>(in.Number()));
    f.balls().push_back(b);
  }
  const int robots = in.Get<uint8_t>() % 8;
  for (int i = 0; i < robots; ++i) {
    idl::DetectedRobot r;
    r.team(static_cast<idl::Team>(in.Get<uint8_t>() % 3));
    r.id(in.Get<uint8_t>());
    r.position().x(in.Number());
    r.position().y(in.Number());
    r.orientation(in.Number());
    r.height(in.Number());
    r.confidence(static_cast<float>(in.Number()));
    f.robots().push_back(r);
  }
  return f;
}

idl::WorldState MakeState(Bytes& in) {
  idl::WorldState s;
  s.sim_time_ns(in.Get<int64_t>());
  s.frame(in.Get<uint64_t>());
  s.ball().position(in.Vec3());
  s.ball().velocity(in.Vec3());
  const int robots = in.Get<uint8_t>() % 8;
  for (int i = 0; i < robots; ++i) {
    idl::RobotState r;
    r.team(static_cast<idl::Team>(in.Get<uint8_t>() % 3));
    r.id(in.Get<uint8_t>());
    r.on_field(in.Get<uint8_t>() % 2 == 0);
    r.position(in.Vec3());
    r.yaw(in.Number());
    r.linear_velocity(in.Vec3());
    r.angular_velocity(in.Vec3());
    s.robots().push_back(r);
  }
  return s;
}

void FuzzGeometry(const idl::SslField& field) {
  std::vector<uint8_t> bytes;
  if (vision::EncodeGeometry(field, &bytes) != vision::VisionError::kOk) {
    Require(bytes.empty());
    return;
  }
  wire::vision::SSL_WrapperPacket p;
  RequireParses(bytes, &p);
  Require(p.has_geometry() && p.geometry().calib_size() == static_cast<int>(field.cameras().size()));
  for (const auto& l : p.geometry().field().field_lines())
    Require(Finite(l.p1().x()) && Finite(l.p1().y()) && Finite(l.p2().x()) && Finite(l.p2().y()));
  for (const auto& c : p.geometry().calib())
    Require(Finite(c.tx()) && Finite(c.ty()) && Finite(c.tz()) && Finite(c.focal_length()));
}

void FuzzDetection(const idl::CameraFrame& frame, const idl::SslField& field, vision::WireClock clock, double now) {
  if (vision::CheckCameraFrame(frame) != vision::VisionError::kOk) return;
  vision::FrameTimes times{};
  if (clock.ForCamera(frame.camera_id(), frame.capture_time_ns(), frame.sent_time_ns(), now, &times) !=
      vision::VisionError::kOk)
    return;
  Require(times.t_capture > 0.0 && times.t_sent >= times.t_capture);
  const idl::CameraInfo* camera = vision::FindCamera(field, frame.camera_id());
  if (camera != nullptr && vision::CheckField(field) != vision::VisionError::kOk) camera = nullptr;
  wire::vision::SSL_WrapperPacket p;
  RequireParses(vision::EncodeDetection(frame, times, camera), &p);
  const auto& d = p.detection();
  Require(static_cast<size_t>(d.balls_size() + d.robots_blue_size() + d.robots_yellow_size()) ==
          frame.balls().size() + frame.robots().size());
  for (const auto& b : d.balls())
    Require(Finite(b.x()) && Finite(b.y()) && Finite(b.z()) && Finite(b.pixel_x()) && Finite(b.pixel_y()));
  for (const auto* team : {&d.robots_blue(), &d.robots_yellow()})
    for (const auto& r : *team)
      Require(Finite(r.x()) && Finite(r.y()) && Finite(r.orientation()) && Finite(r.pixel_x()) && Finite(r.pixel_y()) &&
              r.robot_id() <= 15 && std::abs(r.orientation()) <= 3.1416f);
}

void FuzzTracked(const idl::WorldState& state, vision::WireClock clock, double now) {
  double timestamp = 0.0;
  if (clock.ForWorldState(state.sim_time_ns(), now, &timestamp) != vision::VisionError::kOk) return;
  std::vector<uint8_t> bytes;
  if (vision::EncodeTracked(state, {"uuid", "fuzz"}, timestamp, &bytes) != vision::VisionError::kOk) {
    Require(bytes.empty());
    return;
  }
  wire::vision::TrackerWrapperPacket p;
  RequireParses(bytes, &p);
  for (const auto& r : p.tracked_frame().robots())
    Require(Finite(r.pos().x()) && Finite(r.pos().y()) && Finite(r.vel_angular()) && r.robot_id().id() <= 15);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  Bytes in(data, size);
  const uint8_t m = in.Get<uint8_t>() % 3;
  vision::WireClock clock(m == 0   ? vision::ClockMode::kRun
                          : m == 1 ? vision::ClockMode::kUnix
                                   : vision::ClockMode::kSim);
  clock.AddRunEpoch(in.Get<int64_t>());  // any int64 a rogue clock sample may carry
  const double now = in.Number() * 1e9;
  const idl::SslField field = MakeField(in);
  const idl::CameraFrame frame = MakeFrame(in);
  const idl::WorldState state = MakeState(in);
  FuzzGeometry(field);
  FuzzDetection(frame, field, clock, now);
  FuzzTracked(state, clock, now);
  return 0;
}
