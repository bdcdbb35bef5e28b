#include "loader/legged_scene_yaml.h"
#include "loader/text_file.h"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>
#include <array>

#include <exception>
#include <filesystem>
#include <map>
#include <optional>
#include <utility>

#include "core/legged/nao_types.h"
#include "loader/realism_yaml.h"
#include "loader/yaml_reader.h"

namespace turf {

namespace {

using yaml::Errors;
using yaml::MapReader;

constexpr uintmax_t kMaxSceneBytes = 1 << 20;
constexpr uintmax_t kMaxModelBytes = 16 << 20;

// Every key of `motors` is a number.
void ReadMotors(MapReader m, MotorParams* p) {
  static constexpr std::pair<const char*, double MotorParams::*> kKeys[] = {
      {"max_torque", &MotorParams::max_torque},
      {"max_speed", &MotorParams::max_speed},
      {"velocity_kp", &MotorParams::velocity_kp},
      {"velocity_kd", &MotorParams::velocity_kd},
      {"position_kp", &MotorParams::position_kp},
      {"position_kd", &MotorParams::position_kd},
      {"max_reference_lead", &MotorParams::max_reference_lead}};
  for (const auto& [key, field] : kKeys) m.Number(key, &(p->*field));
  m.Finish();
}

void ReadField(MapReader m, Field3d* f) {
  f->enabled = true;
  m.Number("length", &f->length);
  m.Number("width", &f->width);
  m.Number("goal_width", &f->goal_width);
  m.Number("goal_depth", &f->goal_depth);
  m.Number("goal_height", &f->goal_height);
  m.Number("goal_wall", &f->goal_wall);
  m.Number("ball_radius", &f->ball_radius);
  m.Number("ball_mass", &f->ball_mass);
  m.Point("ball_start", &f->ball_x, &f->ball_y);
  m.Numbers("ball_friction", f->ball_friction.data(), 3);
  m.Int("ball_condim", &f->ball_condim);
  m.Int("ball_priority", &f->ball_priority);
  m.Numbers("ball_solref", f->ball_solref.data(), 2);
  std::array<double, 2> drag{f->ball_linear_drag, f->ball_angular_drag};
  if (m.Numbers("ball_drag", drag.data(), 2)) {
    f->ball_linear_drag = drag[0];
    f->ball_angular_drag = drag[1];
  }
  m.Number("wall_distance", &f->wall_distance);
  m.Bool("walls", &f->walls);
  m.Finish();
}

// robots[].joints: a list of {name, q, kp, kd}; whether each names a joint of
// the model and q lies in its range, the world checks when it compiles.
void ReadStartJoints(MapReader& m, LeggedRobot* r) {
  m.EachMap("joints", "a list of {name, q, kp, kd}", [r](MapReader j) {
    JointStart start;
    if (!j.String("name", &start.joint)) j.Fail("name", "required");
    j.Number("q", &start.position);
    j.Number("kp", &start.kp);
    j.Number("kd", &start.kd);
    j.Finish();
    r->start_joints.push_back(std::move(start));
  });
}

// robots[].cameras: a list of camera declarations (core/legged/legged_scene.h: CameraDecl); whether a body or
// camera exists and the values' ranges are checked against the model (core/legged/legged_cameras.h).
void ReadCameras(MapReader& m, LeggedRobot* r) {
  const char* what = "a list of {name, body, pos, xyaxes, width, height, hfov_deg, rate_hz, encoding, ...}";
  m.EachMap("cameras", what, [r](MapReader c) {
    CameraDecl d;
    if (!c.String("name", &d.name)) c.Fail("name", "required");
    std::string text;
    if (c.String("body", &text)) d.body = text;
    std::array<double, 3> pos{};
    if (c.Numbers("pos", pos.data(), 3)) d.pos = pos;
    std::array<double, 6> xy{};
    if (c.Numbers("xyaxes", xy.data(), 6)) d.xyaxes = xy;
    int n = 0;
    if (c.Int("width", &n)) d.width = n;
    if (c.Int("height", &n)) d.height = n;
    if (c.Int("jpeg_quality", &n)) d.jpeg_quality = n;
    double v = 0.0;
    if (c.Degrees("hfov_deg", &v)) d.hfov = v;
    if (c.Number("rate_hz", &v)) d.rate_hz = v;
    if (c.Number("noise_stddev", &v)) d.noise_stddev = v;
    if (c.String("encoding", &text)) d.encoding = text;
    bool on = true;
    if (c.Bool("enabled", &on)) d.enabled = on;
    c.Finish();
    r->cameras.push_back(std::move(d));
  });
}

// `nao_type: 0..4`: the model (configs/robots/nao.xml, type 0) built as that 3D-league robot type.
void ReadNaoType(MapReader& m, LeggedRobot* r) {
  int type = -1;
  if (!m.Int("nao_type", &type)) return;
  if (type < 0 || type >= kNaoRobotTypes) return m.Fail("nao_type", fmt::format("{} is not a robot type 0..4", type));
  if (r->model_xml.empty()) return;  // the model's own error is reported
  NaoTypeModel typed = NaoTypeMjcf(r->model_xml, type);
  if (!typed.error.empty()) return m.Fail("nao_type", typed.error);
  r->model_xml = std::move(typed.xml);
  r->model += fmt::format(" (type {})", type);
  r->robot_type = type;
}

// Model files are read once per path, however many robots use them.
void ReadRobot(MapReader m, const std::string& base_dir, std::map<std::string, std::string>* models, LeggedRobot* r) {
  if (!m.String("name", &r->name)) m.Fail("name", "required");
  m.Int("id", &r->id);
  if (m.String("model", &r->model)) {
    const std::string path = (std::filesystem::path(base_dir) / r->model).lexically_normal().string();
    auto it = models->find(path);
    if (it == models->end()) {
      std::string text;
      std::string error;
      if (!ReadTextFile(path, kMaxModelBytes, &text, &error)) {
        m.Fail("model", fmt::format("{}: {}", path, error));
        text.clear();
      }
      it = models->emplace(path, std::move(text)).first;
    }
    r->model_xml = it->second;
  } else {
    m.Fail("model", "required");
  }
  ReadNaoType(m, r);
  m.Number("x", &r->x);
  m.Number("y", &r->y);
  double z = 0.0;
  if (m.Number("z", &z)) r->z = z;
  m.Degrees("yaw_deg", &r->yaw);
  ReadMotors(m.Map("motors"), &r->motors);
  ReadStartJoints(m, r);
  ReadCameras(m, r);
  m.Finish();
}

// A surface's ODE parameters; keys left out stay "not set".
void ReadOdeSurface(MapReader m, OdeSurface* s) {
  m.Number("erp", &s->erp);
  m.Number("cfm", &s->cfm);
  m.Number("slip", &s->slip);
  m.Number("bounce", &s->bounce);
  m.Number("bounce_vel", &s->bounce_vel);
  m.Finish();
}

// `contacts: {law: ode, ...}`: rcssserver3d's contact law (core/legged/ode_contacts.h); `law: ode_friction`: only its
// tangential law (unbounded friction, force-dependent slip) on MuJoCo's normal contact; `law: mujoco` or no block:
// MuJoCo's own.
void ReadContacts(MapReader m, OdeContactLaw* c) {
  std::string law = "mujoco";
  m.String("law", &law);
  if (law != "ode" && law != "ode_friction" && law != "mujoco")
    m.Fail("law", "must be \"ode\", \"ode_friction\" or \"mujoco\"");
  c->enabled = law == "ode" || law == "ode_friction";
  c->ode_normal = law == "ode";
  m.Number("reference_step", &c->reference_step);
  m.Number("surface_layer", &c->surface_layer);
  m.Number("world_erp", &c->world_erp);
  m.Number("world_cfm", &c->world_cfm);
  if (m.Has("robot")) ReadOdeSurface(m.Map("robot"), &c->robot);
  if (m.Has("ground")) ReadOdeSurface(m.Map("ground"), &c->ground);
  if (m.Has("ball")) ReadOdeSurface(m.Map("ball"), &c->ball);
  m.Finish();
}

// `joint_stops: {law: ode, ...}`: rcssserver3d's hinge stops (core/legged/legged_scene.h: OdeJointStops);
// `law: mujoco` or no block: MuJoCo's limits.
void ReadJointStops(MapReader m, OdeJointStops* j) {
  std::string law = "mujoco";
  m.String("law", &law);
  if (law != "ode" && law != "mujoco") m.Fail("law", "must be \"ode\" or \"mujoco\"");
  j->enabled = law == "ode";
  m.Number("step", &j->step);
  m.Number("erp", &j->erp);
  m.Number("bounce", &j->bounce);
  m.Number("fudge", &j->fudge);
  m.Bool("hold_commands_at_stop", &j->hold_commands_at_stop);
  m.Finish();
}

void ReadScene(MapReader m, const std::string& base_dir, LeggedScene* s, Errors* errors) {
  std::string kind;
  if (!m.String("kind", &kind) || kind != "legged") m.Fail("kind", "must be \"legged\"");
  m.String("name", &s->name);
  m.Uint64("seed", &s->seed);
  m.Number("ground_friction", &s->ground_friction);
  yaml::ReadPhysics(m.Map("physics"), &s->physics, [&](yaml::MapReader& p) {
    p.Bool("sensors_after_step", &s->physics.sensors_after_step);
    p.Int("island_threads", &s->physics.island_threads);
    p.Number("motor_impulse_window", &s->physics.motor_impulse_window);
    p.Number("fluid_density", &s->physics.fluid_density);
    p.Number("fluid_viscosity", &s->physics.fluid_viscosity);
    std::array<double, 2> drag{s->physics.body_linear_drag, s->physics.body_angular_drag};
    if (p.Numbers("body_drag", drag.data(), 2)) {
      s->physics.body_linear_drag = drag[0];
      s->physics.body_angular_drag = drag[1];
    }
  });
  {
    MapReader r = m.Map("rates");
    r.Number("joint_state_hz", &s->rates.joint_state_hz);
    r.Finish();
  }
  if (m.Has("field")) ReadField(m.Map("field"), &s->field);
  if (m.Has("contacts")) ReadContacts(m.Map("contacts"), &s->contacts);
  if (m.Has("joint_stops")) ReadJointStops(m.Map("joint_stops"), &s->joint_stops);
  ReadSceneRealism(m, base_dir, &s->realism, errors);  // encoder and imu apply to legged robots
  const YAML::Node robots = m.Child("robots");
  if (robots && !robots.IsSequence()) {
    m.Fail("robots", "expected a list");
  } else if (robots && robots.size() > kMaxLeggedRobots) {  // before any model is read
    m.Fail("robots", fmt::format("at most {} robots (the list has {})", kMaxLeggedRobots, robots.size()));
  } else if (robots) {
    std::map<std::string, std::string> models;
    for (size_t i = 0; i < robots.size(); ++i) {
      LeggedRobot r;
      ReadRobot(MapReader(robots[i], fmt::format("robots[{}]", i), errors), base_dir, &models, &r);
      s->robots.push_back(std::move(r));
    }
  }
  m.Finish();
}

LeggedSceneLoadResult Parse(const std::string& yaml_text, const std::string& base_dir) {
  LeggedSceneLoadResult result;
  const std::optional<YAML::Node> document = yaml::LoadSceneDocument(yaml_text, &result.errors);
  if (!document) return result;
  LeggedScene scene;
  ReadScene(MapReader(*document, "", &result.errors), base_dir, &scene, &result.errors);
  if (result.errors.empty()) {
    for (std::string& e : ValidateLeggedScene(scene)) result.errors.push_back(std::move(e));
  }
  if (result.errors.empty()) result.scene = std::move(scene);
  return result;
}

}  // namespace

bool IsLeggedSceneFile(const std::string& path) {
  try {
    std::string text;
    std::string error;
    if (!ReadTextFile(path, kMaxSceneBytes, &text, &error)) return false;
    const YAML::Node root = YAML::Load(text);
    return root.IsMap() && root["kind"] && root["kind"].IsScalar() && root["kind"].Scalar() == "legged";
  } catch (const std::exception&) {
    return false;
  }
}

LeggedSceneLoadResult ParseLeggedSceneYaml(const std::string& yaml_text, const std::string& base_dir) {
  return yaml::ParseGuarded<LeggedSceneLoadResult>([&] { return Parse(yaml_text, base_dir); });
}

LeggedSceneLoadResult LoadLeggedSceneFile(const std::string& path) {
  const std::string base_dir = std::filesystem::path(path).parent_path().string();
  return yaml::LoadFile<LeggedSceneLoadResult>(
      path, kMaxSceneBytes, [&](const std::string& text) { return ParseLeggedSceneYaml(text, base_dir); });
}

}  // namespace turf
