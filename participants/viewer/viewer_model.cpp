#include "participants/viewer/viewer_model.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <vector>

#include "participants/viewer/legged_json.h"
#include "participants/viewer/viewer_json.h"

namespace turf::viewer {

namespace {

bool Finite(std::initializer_list<double> values) {
  for (double v : values)
    if (!std::isfinite(v)) return false;
  return true;
}
bool Finite(const idl::Vec3& v) { return Finite({v.x(), v.y(), v.z()}); }
bool Finite(const idl::Vec2& v) { return Finite({v.x(), v.y()}); }
bool Finite(const idl::Quat& q) { return Finite({q.w(), q.x(), q.y(), q.z()}); }
bool KnownTeam(idl::Team t) { return t == idl::TEAM_BLUE || t == idl::TEAM_YELLOW; }

// A size the page can draw: positive and below a kilometre.
bool Size(double v) { return std::isfinite(v) && v > 0.0 && v < 1000.0; }
bool NonNegative(double v) { return std::isfinite(v) && v >= 0.0 && v < 1000.0; }

}  // namespace

ViewerModel::ViewerModel(std::string client, std::string prefix)
    : client_(std::move(client)), prefix_(std::move(prefix)) {}

SampleError ViewerModel::OnWorldState(const idl::WorldState& s) {
  if (s.robots().size() > kMaxRobots) return SampleError::kTooMany;
  const idl::BallState& b = s.ball();
  if (!Finite(b.position()) || !Finite(b.velocity())) return SampleError::kNotFinite;
  for (const idl::RobotState& r : s.robots()) {
    if (!KnownTeam(r.team())) return SampleError::kUnknownEnum;
    if (!Finite(r.position()) || !Finite(r.linear_velocity()) || !Finite(r.angular_velocity()) || !Finite({r.yaw()}))
      return SampleError::kNotFinite;
  }
  state_ = s;
  return SampleError::kOk;
}

SampleError ViewerModel::OnClock(const idl::Clock& c) {
  if (!Finite({c.speed(), c.real_time_factor(), c.step_s()})) return SampleError::kNotFinite;
  if (c.mode() > idl::TIME_LOCKSTEP) return SampleError::kUnknownEnum;
  clock_ = c;
  return SampleError::kOk;
}

SampleError ViewerModel::OnField(const idl::SslField& f) {
  if (f.cameras().size() > kMaxCameras) return SampleError::kTooMany;
  if (!Finite({f.field_length(), f.field_width(), f.boundary_width(), f.boundary_width_goal_line(), f.goal_width(),
               f.goal_depth(), f.penalty_area_depth(), f.penalty_area_width(), f.center_circle_radius(),
               f.line_thickness(), f.ball_radius(), f.max_robot_radius(), f.robot_height()}))
    return SampleError::kNotFinite;
  if (!Size(f.field_length()) || !Size(f.field_width()) || !Size(f.ball_radius()) || !Size(f.max_robot_radius()) ||
      !NonNegative(f.boundary_width()) || !NonNegative(f.boundary_width_goal_line()) || !NonNegative(f.goal_width()) ||
      !NonNegative(f.goal_depth()) || !NonNegative(f.penalty_area_depth()) || !NonNegative(f.penalty_area_width()) ||
      !NonNegative(f.center_circle_radius()) || !NonNegative(f.line_thickness()) || !NonNegative(f.robot_height()))
    return SampleError::kBadSize;
  for (const idl::CameraInfo& c : f.cameras())
    if (!Finite(c.area_min()) || !Finite(c.area_max())) return SampleError::kNotFinite;
  field_ = f;
  legged_.reset();
  links_.clear();
  return SampleError::kOk;
}

SampleError ViewerModel::OnCamera(const idl::CameraFrame& f) {
  if (f.balls().size() > kMaxRobots || f.robots().size() > kMaxRobots) return SampleError::kTooMany;
  for (const idl::DetectedBall& b : f.balls())
    if (!Finite(b.position()) || !Finite({b.confidence()})) return SampleError::kNotFinite;
  for (const idl::DetectedRobot& r : f.robots()) {
    if (!KnownTeam(r.team())) return SampleError::kUnknownEnum;
    if (!Finite(r.position()) || !Finite({r.orientation(), r.confidence()})) return SampleError::kNotFinite;
  }
  if (frames_.count(f.camera_id()) == 0 && frames_.size() >= kMaxCameras) return SampleError::kTooMany;
  frames_[f.camera_id()] = f;
  return SampleError::kOk;
}

SampleError ViewerModel::OnStats(const idl::SensorStats& s) {
  if (s.streams().size() > kMaxStreams) return SampleError::kTooMany;
  if (!Finite({s.window_s()})) return SampleError::kNotFinite;
  for (const idl::StreamStats& st : s.streams()) {
    if (!Finite({st.rate_hz(), st.loss_ratio(), st.latency_mean(), st.latency_stddev()}))
      return SampleError::kNotFinite;
    if (st.name().size() > 128) return SampleError::kBadSize;
  }
  stats_ = s;
  return SampleError::kOk;
}

SampleError ViewerModel::OnLeggedScene(const idl::LeggedSceneInfo& s) {
  if (s.robots().size() > kMaxLeggedRobots) return SampleError::kTooMany;
  if (s.name().size() > kMaxNameLength) return SampleError::kBadSize;
  if (!Finite({s.field_length(), s.field_width(), s.goal_width(), s.goal_depth(), s.goal_height(), s.ball_radius()}))
    return SampleError::kNotFinite;
  if (s.has_field() && (!Size(s.field_length()) || !Size(s.field_width()) || !Size(s.ball_radius()) ||
                        !NonNegative(s.goal_width()) || !NonNegative(s.goal_depth()) || !NonNegative(s.goal_height())))
    return SampleError::kBadSize;
  for (size_t i = 0; i < s.robots().size(); ++i) {
    const idl::RobotDescription& r = s.robots()[i];
    if (r.geoms().size() > kMaxBodies) return SampleError::kTooMany;
    if (r.robot().empty() || r.robot().size() > kMaxNameLength || r.model().size() > kMaxNameLength)
      return SampleError::kBadSize;
    for (size_t j = 0; j < i; ++j)
      if (s.robots()[j].robot() == r.robot()) return SampleError::kDuplicate;
    for (const idl::RobotGeom& g : r.geoms()) {
      if (g.shape() > idl::GEOM_OTHER) return SampleError::kUnknownEnum;
      if (!Finite(g.size()) || !Finite(g.position()) || !Finite(g.orientation())) return SampleError::kNotFinite;
      if (g.body().size() > kMaxNameLength) return SampleError::kBadSize;
      for (double v : {g.size().x(), g.size().y(), g.size().z()})
        if (!NonNegative(v)) return SampleError::kBadSize;
    }
  }
  legged_ = s;
  field_.reset();
  state_.reset();  // an SSL state would show robots that are not there
  frames_.clear();
  // Poses of robots this scene does not have are from another run.
  for (auto it = links_.begin(); it != links_.end();) {
    const auto& robots = s.robots();
    const bool known = std::any_of(robots.begin(), robots.end(),
                                   [&](const idl::RobotDescription& r) { return r.robot() == it->first; });
    it = known ? std::next(it) : links_.erase(it);
  }
  return SampleError::kOk;
}

SampleError ViewerModel::OnLinks(const idl::LinkState& l) {
  if (l.links().size() > kMaxBodies) return SampleError::kTooMany;
  if (l.robot().empty() || l.robot().size() > kMaxNameLength) return SampleError::kBadSize;
  for (const idl::LinkPose& p : l.links()) {
    if (!Finite(p.position()) || !Finite(p.orientation())) return SampleError::kNotFinite;
    if (p.name().size() > kMaxNameLength) return SampleError::kBadSize;
  }
  if (links_.count(l.robot()) == 0 && links_.size() >= kMaxLeggedRobots) return SampleError::kTooMany;
  links_[l.robot()] = l;
  return SampleError::kOk;
}

PageRequest ViewerModel::OnPageMessage(std::string_view text) {
  PageRequest r = ParsePageRequest(text, PageScene{field_ ? &*field_ : nullptr, legged_ ? &*legged_ : nullptr});
  if (r.error != PageError::kOk) {
    ++refused_pages_;
    return r;
  }
  r.control.client(client_);
  return r;
}

std::string ViewerModel::Hello() const { return HelloJson(prefix_); }

std::string ViewerModel::Field() const {
  if (legged_) return LeggedSceneJson(*legged_);
  return field_ ? FieldJson(*field_) : std::string();
}

std::string ViewerModel::State() const {
  if (legged_) {
    if (!has_state()) return {};
    const bool ball = state_ && legged_->has_field();
    return LeggedStateJson(ball ? &*state_ : nullptr, *legged_, links_, clock_,
                           {refused_pages_, control_matched_, sim_gone_since_unix_ms_});
  }
  if (!state_) return {};
  // What the cameras saw lately: frames from the last kMaxFrameAgeNs of sim
  // time (none from the future, as after a reset).
  std::vector<const idl::CameraFrame*> recent;
  const int64_t now = state_->sim_time_ns();
  for (const auto& [id, frame] : frames_) {
    const int64_t age = now - frame.capture_time_ns();
    if (age >= 0 && age <= kMaxFrameAgeNs) recent.push_back(&frame);
  }
  return StateJson(*state_, clock_, recent, {refused_pages_, control_matched_, sim_gone_since_unix_ms_});
}

std::string ViewerModel::Stats() const { return stats_ ? StatsJson(*stats_) : std::string(); }

}  // namespace turf::viewer
