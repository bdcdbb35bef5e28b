#include "loader/scene_yaml.h"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <array>
#include <filesystem>
#include <optional>
#include <utility>

#include "loader/realism_yaml.h"
#include "loader/yaml_reader.h"

namespace turf {

namespace {

using yaml::Errors;
using yaml::MapReader;

constexpr uintmax_t kMaxFileBytes = 1 << 20;  // scene files are a few kB
constexpr double kRadiansPerDegree = 3.14159265358979323846 / 180.0;

void ReadRates(MapReader m, RateParams* r) {
  m.Number("world_state_hz", &r->world_state_hz);
  m.Number("command_timeout", &r->command_timeout);
  m.Finish();
}

void ReadField(MapReader m, FieldParams* f) {
  // The division's dimensions first; every other key overrides them.
  std::string division;
  if (m.String("division", &division)) {
    if (division == "A") {
      *f = FieldForDivision(Division::kA);
    } else if (division == "B") {
      *f = FieldForDivision(Division::kB);
    } else {
      m.Fail("division", fmt::format("expected A or B, got \"{}\"", division));
    }
  }
  m.Number("length", &f->length);
  m.Number("width", &f->width);
  m.Number("boundary_width", &f->boundary_width);
  m.Number("boundary_width_goal_line", &f->boundary_width_goal_line);
  m.Number("goal_width", &f->goal_width);
  m.Number("goal_depth", &f->goal_depth);
  m.Number("goal_height", &f->goal_height);
  m.Number("goal_wall_thickness", &f->goal_wall_thickness);
  m.Number("penalty_area_depth", &f->penalty_area_depth);
  m.Number("penalty_area_width", &f->penalty_area_width);
  m.Number("center_circle_radius", &f->center_circle_radius);
  m.Number("line_thickness", &f->line_thickness);
  m.Number("goal_center_to_penalty_mark", &f->goal_center_to_penalty_mark);
  m.Number("wall_height", &f->wall_height);
  m.Number("wall_thickness", &f->wall_thickness);
  m.Number("friction", &f->friction);
  m.Finish();
}

void ReadBall(MapReader m, Scene* s) {
  BallParams* b = &s->ball;
  m.Point("start", &s->ball_start_x, &s->ball_start_y);
  m.Number("radius", &b->radius);
  m.Number("mass", &b->mass);
  m.Number("acc_slide", &b->acc_slide);
  m.Number("acc_roll", &b->acc_roll);
  m.Number("k_switch", &b->k_switch);
  m.Number("floor_restitution", &b->floor_restitution);
  m.Number("wall_restitution", &b->wall_restitution);
  m.Number("chip_damping_xy_first_hop", &b->chip_damping_xy_first_hop);
  m.Number("chip_damping_xy_other_hops", &b->chip_damping_xy_other_hops);
  m.Finish();
}

void ReadDrive(MapReader m, DriveParams* d) {
  m.Number("max_speed", &d->max_speed);
  m.Number("max_angular_speed", &d->max_angular_speed);
  m.Number("acc_speedup", &d->acc_speedup);
  m.Number("acc_brake", &d->acc_brake);
  m.Number("acc_angular", &d->acc_angular);
  std::array<double, 4> degrees{};
  if (m.Numbers("wheel_angles_deg", degrees.data(), degrees.size())) {
    for (size_t i = 0; i < degrees.size(); ++i) d->wheel_angles[i] = degrees[i] * kRadiansPerDegree;
  }
  m.Number("wheel_distance", &d->wheel_distance);
  m.Number("wheel_radius", &d->wheel_radius);
  m.Finish();
}

void ReadKicker(MapReader m, KickerParams* k) {
  m.Number("max_flat_speed", &k->max_flat_speed);
  m.Number("max_chip_speed", &k->max_chip_speed);
  m.Degrees("default_chip_angle_deg", &k->default_chip_angle);
  m.Number("reach", &k->reach);
  m.Number("arm_time", &k->arm_time);
  m.Finish();
}

void ReadDribbler(MapReader m, DribblerParams* d) {
  m.Number("restitution", &d->restitution);
  m.Number("max_force", &d->max_force);
  m.Number("stiffness", &d->stiffness);
  m.Number("damping", &d->damping);
  m.Number("capture_distance", &d->capture_distance);
  m.Finish();
}

void ReadRobot(MapReader m, RobotParams* r) {
  m.Number("radius", &r->radius);
  m.Number("height", &r->height);
  m.Number("mass", &r->mass);
  m.Number("center_to_dribbler", &r->center_to_dribbler);
  m.Number("friction", &r->friction);
  ReadDrive(m.Map("drive"), &r->drive);
  ReadKicker(m.Map("kicker"), &r->kicker);
  ReadDribbler(m.Map("dribbler"), &r->dribbler);
  m.Finish();
}

void ReadCameras(MapReader m, CameraParams* c) {
  m.Number("rate_hz", &c->rate_hz);
  m.Number("height", &c->height);
  m.Number("overlap", &c->overlap);
  m.Number("focal_length", &c->focal_length);
  m.Int("image_width", &c->image_width);
  m.Int("image_height", &c->image_height);
  m.Finish();
}

// Where each listed robot came from, to point ValidateScene's findings at it.
struct RobotSource {
  Team team;
  int id;
  std::string path;
};

// One entry of teams.<team>; appended to the scene only when it is sound.
void ReadRobotSetup(MapReader m, Team team, Scene* scene, std::vector<RobotSource>* sources, Errors* errors) {
  const size_t errors_before = errors->size();
  RobotSetup setup;
  setup.team = team;
  const bool has_id = m.Has("id");
  m.Int("id", &setup.id);
  m.Bool("on_field", &setup.on_field);
  const bool has_x = m.Has("x");
  const bool has_y = m.Has("y");
  m.Number("x", &setup.pose.x);
  m.Number("y", &setup.pose.y);
  m.Degrees("theta_deg", &setup.pose.theta);
  m.Finish();
  if (errors->size() != errors_before) return;

  if (!has_id) {
    m.Fail("id", "required");
  } else if (setup.id < 0 || setup.id >= scene->robots_per_team) {
    m.Fail("id", fmt::format("must be in [0, robots_per_team = {}), got {}", scene->robots_per_team, setup.id));
  } else {
    for (const RobotSource& source : *sources) {
      if (source.team == team && source.id == setup.id)
        m.Fail("id", fmt::format("robot {} {} is already listed at {}", TeamName(team), setup.id, source.path));
    }
  }
  if (setup.on_field && !has_x) m.Fail("x", "required for a robot on the field");
  if (setup.on_field && !has_y) m.Fail("y", "required for a robot on the field");
  if (errors->size() != errors_before) return;
  scene->robots.push_back(setup);
  sources->push_back({team, setup.id, m.path()});
}

void ReadTeams(MapReader m, Scene* scene, std::vector<RobotSource>* sources, Errors* errors) {
  for (Team team : {Team::kBlue, Team::kYellow}) {
    const std::string path = m.PathOf(TeamName(team));
    const YAML::Node list = m.Child(TeamName(team));
    if (list.IsNull()) continue;
    if (!list.IsSequence()) {
      m.Fail(TeamName(team), "expected a list of robots");
      continue;
    }
    if (list.size() > static_cast<size_t>(kMaxRobotsPerTeam)) {
      m.Fail(TeamName(team), fmt::format("at most {} robots, got {}", kMaxRobotsPerTeam, list.size()));
      continue;
    }
    size_t index = 0;
    for (const YAML::Node& entry : list) {
      ReadRobotSetup(MapReader(entry, fmt::format("{}[{}]", path, index++), errors), team, scene, sources, errors);
    }
  }
  m.Finish();
}

void ReadScene(MapReader m, const std::string& base_dir, Scene* s, std::vector<RobotSource>* sources, Errors* errors) {
  m.String("name", &s->name);
  m.Uint64("seed", &s->seed);
  yaml::ReadPhysics(m.Map("physics"), &s->physics);
  ReadRates(m.Map("rates"), &s->rates);
  ReadField(m.Map("field"), &s->field);
  ReadBall(m.Map("ball"), s);
  ReadRobot(m.Map("robot"), &s->robot);
  m.Int("robots_per_team", &s->robots_per_team);  // before teams: ids are checked against it
  ReadTeams(m.Map("teams"), s, sources, errors);
  ReadCameras(m.Map("cameras"), &s->cameras);
  ReadSceneRealism(m, base_dir, &s->realism, errors);
  m.Finish();
}

// ValidateScene names robots as "robot <team> <id>: ..."; add the YAML path.
std::string WithRobotPath(std::string error, const std::vector<RobotSource>& sources) {
  for (const RobotSource& source : sources) {
    const std::string who = fmt::format("robot {} {}:", TeamName(source.team), source.id);
    if (error.compare(0, who.size(), who) == 0) return source.path + ": " + error;
  }
  return error;
}

SceneLoadResult Parse(const std::string& yaml_text, const std::string& base_dir) {
  SceneLoadResult result;
  const std::optional<YAML::Node> document = yaml::LoadSceneDocument(yaml_text, &result.errors);
  if (!document) return result;
  Scene scene;
  std::vector<RobotSource> sources;
  ReadScene(MapReader(*document, "", &result.errors), base_dir, &scene, &sources, &result.errors);
  for (std::string& error : ValidateScene(scene)) result.errors.push_back(WithRobotPath(std::move(error), sources));
  if (result.errors.empty()) result.scene = std::move(scene);
  return result;
}

}  // namespace

SceneLoadResult ParseSceneYaml(const std::string& yaml_text, const std::string& base_dir) {
  return yaml::ParseGuarded<SceneLoadResult>([&] { return Parse(yaml_text, base_dir); });
}

SceneLoadResult LoadSceneFile(const std::string& path) {
  const std::string base_dir = std::filesystem::path(path).parent_path().string();
  return yaml::LoadFile<SceneLoadResult>(path, kMaxFileBytes,
                                         [&](const std::string& text) { return ParseSceneYaml(text, base_dir); });
}

}  // namespace turf
