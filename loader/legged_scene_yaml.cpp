#include "loader/legged_scene_yaml.h"
#include "loader/text_file.h"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <exception>
#include <filesystem>
#include <map>
#include <optional>

#include "loader/realism_yaml.h"
#include "loader/yaml_reader.h"

namespace turf {

namespace {

using yaml::Errors;
using yaml::MapReader;

constexpr uintmax_t kMaxSceneBytes = 1 << 20;
constexpr uintmax_t kMaxModelBytes = 16 << 20;

void ReadMotors(MapReader m, MotorParams* p) {
  m.Number("max_torque", &p->max_torque);
  m.Number("max_speed", &p->max_speed);
  m.Number("velocity_kp", &p->velocity_kp);
  m.Number("velocity_kd", &p->velocity_kd);
  m.Number("position_kp", &p->position_kp);
  m.Number("position_kd", &p->position_kd);
  m.Number("max_reference_lead", &p->max_reference_lead);
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
  double start[2] = {f->ball_x, f->ball_y};
  if (m.Numbers("ball_start", start, 2)) {
    f->ball_x = start[0];
    f->ball_y = start[1];
  }
  m.Number("wall_distance", &f->wall_distance);
  m.Finish();
}

// robots[].joints: a list of {name, q, kp, kd}; whether each names a joint of
// the model and q lies in its range, the world checks when it compiles.
void ReadStartJoints(MapReader& m, LeggedRobot* r) {
  const YAML::Node joints = m.Child("joints");
  if (!joints.IsDefined() || joints.IsNull()) return;  // absent
  if (!joints.IsSequence()) {
    m.Fail("joints", "expected a list of {name, q, kp, kd}");
    return;
  }
  for (size_t i = 0; i < joints.size(); ++i) {
    MapReader j(joints[i], fmt::format("{}.joints[{}]", m.path(), i), m.errors());
    JointStart start;
    if (!j.String("name", &start.joint)) j.Fail("name", "required");
    j.Number("q", &start.position);
    j.Number("kp", &start.kp);
    j.Number("kd", &start.kd);
    j.Finish();
    r->start_joints.push_back(std::move(start));
  }
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
  m.Number("x", &r->x);
  m.Number("y", &r->y);
  double z = 0.0;
  if (m.Number("z", &z)) r->z = z;
  m.Degrees("yaw_deg", &r->yaw);
  ReadMotors(m.Map("motors"), &r->motors);
  ReadStartJoints(m, r);
  m.Finish();
}

void ReadScene(MapReader m, const std::string& base_dir, LeggedScene* s, Errors* errors) {
  std::string kind;
  if (!m.String("kind", &kind) || kind != "legged") m.Fail("kind", "must be \"legged\"");
  m.String("name", &s->name);
  m.Uint64("seed", &s->seed);
  m.Number("ground_friction", &s->ground_friction);
  yaml::ReadPhysics(m.Map("physics"), &s->physics);
  {
    MapReader r = m.Map("rates");
    r.Number("joint_state_hz", &s->rates.joint_state_hz);
    r.Finish();
  }
  if (m.Has("field")) ReadField(m.Map("field"), &s->field);
  ReadSceneRealism(m, &s->realism, errors);  // encoder and imu apply to legged robots
  const YAML::Node robots = m.Child("robots");
  if (robots && !robots.IsSequence()) {
    m.Fail("robots", "expected a list");
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
