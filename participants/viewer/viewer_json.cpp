#include "participants/viewer/viewer_json.h"

#include <nlohmann/json.hpp>

#include <cmath>

#include "core/errors.h"
#include "participants/viewer/json_util.h"
#include "participants/viewer/legged_json.h"
#include "participants/viewer/page_request.h"

namespace turf::viewer {

namespace {

using json_util::Dump;
using json_util::Ns;
using json_util::R;
using nlohmann::json;

const char* TeamName(idl::Team team) { return team == idl::TEAM_BLUE ? "blue" : "yellow"; }

json Detection(const idl::CameraFrame& f) {
  json balls = json::array();
  for (const idl::DetectedBall& b : f.balls())
    balls.push_back({R(b.position().x()), R(b.position().y()), R(b.position().z()), R(b.confidence(), 1e3)});
  json robots = json::array();
  for (const idl::DetectedRobot& r : f.robots()) {
    robots.push_back({{"team", TeamName(r.team())},
                      {"id", r.id()},
                      {"p", {R(r.position().x()), R(r.position().y())}},
                      {"yaw", R(r.orientation())},
                      {"conf", R(r.confidence(), 1e3)}});
  }
  return {{"camera", f.camera_id()}, {"t", Ns(f.capture_time_ns())}, {"balls", balls}, {"robots", robots}};
}

json Ball(const idl::BallState& b) {
  return {{"p", {R(b.position().x()), R(b.position().y()), R(b.position().z())}},
          {"v", {R(b.velocity().x(), 1e3), R(b.velocity().y(), 1e3), R(b.velocity().z(), 1e3)}}};
}

// What every state message ends with: the clock (once known) and the viewer's condition.
void AddClockAndViewer(const std::optional<idl::Clock>& clock, const ViewerInfo& viewer, json* out) {
  (*out)["viewer"] = {{"refused", viewer.refused}, {"control", viewer.control}};
  if (viewer.gone_since_unix_ms > 0) (*out)["viewer"]["gone_since"] = viewer.gone_since_unix_ms;
  if (!clock) return;
  (*out)["clock"] = {{"paused", clock->paused()},
                     {"mode", TimeModeName(clock->mode())},
                     {"speed", R(clock->speed(), 1e3)},
                     {"rtf", R(clock->real_time_factor(), 1e3)}};
}

}  // namespace

const char* OpName(idl::ControlOp op) { return EnumName(op, kPageOps); }
const char* TimeModeName(idl::TimeMode mode) { return EnumName(mode, kPageTimeModes); }

std::string HelloJson(const std::string& prefix) {
  return Dump(json{{"type", "hello"},
                   {"version", kProtocolVersion},
                   {"prefix", prefix},
                   {"presets", {"ideal", "realistic", "harsh"}},
                   {"max_message", kMaxPageMessage}});
}

std::string FieldJson(const idl::SslField& f) {
  json cameras = json::array();
  for (const idl::CameraInfo& c : f.cameras()) {
    cameras.push_back({{"id", c.id()},
                       {"min", {R(c.area_min().x()), R(c.area_min().y())}},
                       {"max", {R(c.area_max().x()), R(c.area_max().y())}}});
  }
  return Dump(json{{"type", "field"},
                   {"division", f.division() == 2 ? "B" : "A"},
                   {"length", R(f.field_length())},
                   {"width", R(f.field_width())},
                   {"boundary", R(f.boundary_width())},
                   {"boundary_goal", R(f.boundary_width_goal_line())},
                   {"goal_width", R(f.goal_width())},
                   {"goal_depth", R(f.goal_depth())},
                   {"penalty_depth", R(f.penalty_area_depth())},
                   {"penalty_width", R(f.penalty_area_width())},
                   {"center_radius", R(f.center_circle_radius())},
                   {"line", R(f.line_thickness())},
                   {"ball_radius", R(f.ball_radius())},
                   {"robot_radius", R(f.max_robot_radius())},
                   {"robot_height", R(f.robot_height())},
                   {"robots_per_team", f.robots_per_team()},
                   {"cameras", cameras}});
}

std::string StateJson(const idl::WorldState& s, const std::optional<idl::Clock>& clock,
                      const std::vector<const idl::CameraFrame*>& frames, const ViewerInfo& viewer) {
  json robots = json::array();
  for (const idl::RobotState& r : s.robots()) {
    robots.push_back(
        {{"team", TeamName(r.team())},
         {"id", r.id()},
         {"on", r.on_field()},
         {"p", {R(r.position().x()), R(r.position().y())}},
         {"yaw", R(r.yaw())},
         {"v", {R(r.linear_velocity().x(), 1e3), R(r.linear_velocity().y(), 1e3), R(r.angular_velocity().z(), 1e3)}}});
  }
  json detections = json::array();
  for (const idl::CameraFrame* f : frames) detections.push_back(Detection(*f));
  json out{{"type", "state"},        {"t", Ns(s.sim_time_ns())}, {"frame", s.frame()},
           {"ball", Ball(s.ball())}, {"robots", robots},         {"detections", detections}};
  AddClockAndViewer(clock, viewer, &out);
  return Dump(out);
}

std::string LeggedStateJson(const idl::WorldState* ball, const idl::LeggedSceneInfo& scene,
                            const std::map<std::string, idl::LinkState>& links, const std::optional<idl::Clock>& clock,
                            const ViewerInfo& viewer) {
  // Time: the newest of the samples shown.
  int64_t t = ball ? ball->sim_time_ns() : 0;
  uint64_t frame = ball ? ball->frame() : 0;
  for (const auto& [name, l] : links) {
    if (l.sim_time_ns() < t) continue;
    t = l.sim_time_ns();
    frame = l.frame();
  }
  json out{{"type", "state"},
           {"t", Ns(t)},
           {"frame", frame},
           {"robots", json::array()},
           {"detections", json::array()},
           {"links", LinksJson(scene, links)}};
  if (ball) out["ball"] = Ball(ball->ball());
  AddClockAndViewer(clock, viewer, &out);
  return Dump(out);
}

std::string StatsJson(const idl::SensorStats& stats) {
  json streams = json::array();
  for (const idl::StreamStats& st : stats.streams()) {
    streams.push_back({{"name", st.name()},
                       {"rate", R(st.rate_hz(), 1e2)},
                       {"sent", st.sent()},
                       {"lost", st.lost()},
                       {"loss", R(st.loss_ratio())},
                       {"latency", R(st.latency_mean(), 1e6)},
                       {"jitter", R(st.latency_stddev(), 1e6)}});
  }
  return Dump(
      json{{"type", "stats"}, {"t", Ns(stats.sim_time_ns())}, {"window", R(stats.window_s())}, {"streams", streams}});
}

std::string ReplyJson(const idl::SimControlReply& reply) {
  return Dump(json{{"type", "reply"},
                   {"op", OpName(reply.op())},
                   {"ok", reply.result() == idl::RESULT_OK},
                   // ControlError's values are turf::Error's (checked in participants/sim/control_loop.cpp).
                   {"error", ErrorName(static_cast<Error>(reply.error()))},
                   {"reason", reply.reason()},
                   {"t", Ns(reply.sim_time_ns())}});
}

std::string RefusedJson(const std::string& kind, const std::string& detail) {
  return Dump(json{{"type", "refused"}, {"kind", kind}, {"detail", detail}});
}

}  // namespace turf::viewer
