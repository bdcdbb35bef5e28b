#include "loader/realism_yaml.h"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>

#include "loader/text_file.h"
#include "loader/yaml_reader.h"

namespace turf {

using yaml::MapReader;

namespace {

constexpr size_t kMaxRealismBytes = 64 * 1024;

void ReadLink(MapReader m, LinkParams* l) {
  m.Number("latency", &l->latency);
  m.Number("jitter", &l->jitter);
  std::string kind;
  if (m.String("jitter_kind", &kind)) {
    if (kind == "gaussian") {
      l->jitter_kind = JitterKind::kGaussian;
    } else if (kind == "uniform") {
      l->jitter_kind = JitterKind::kUniform;
    } else if (kind == "exponential") {
      l->jitter_kind = JitterKind::kExponential;
    } else {
      m.Fail("jitter_kind", fmt::format("expected gaussian, uniform or exponential, got \"{}\"", kind));
    }
  }
  m.Number("loss", &l->loss);
  if (m.Has("burst")) {
    MapReader b = m.Map("burst");
    l->burst.enabled = true;
    b.Number("p_good_to_bad", &l->burst.p_good_to_bad);
    b.Number("p_bad_to_good", &l->burst.p_bad_to_good);
    b.Number("loss_good", &l->burst.loss_good);
    b.Number("loss_bad", &l->burst.loss_bad);
    b.Finish();
  }
  m.Finish();
}

void ReadCamera(MapReader m, CameraRealism* c) {
  m.Number("robot_position_stddev", &c->robot_position_stddev);
  m.Number("robot_orientation_stddev", &c->robot_orientation_stddev);
  m.Number("ball_position_stddev", &c->ball_position_stddev);
  m.Number("robot_vanish", &c->robot_vanish);
  m.Number("ball_vanish", &c->ball_vanish);
  m.Bool("ball_occlusion", &c->ball_occlusion);
  m.Number("confidence_spread", &c->confidence_spread);
  m.Number("processing_delay", &c->processing_delay);
  ReadLink(m.Map("link"), &c->link);
  m.Finish();
}

}  // namespace

void ReadRealism(MapReader m, SensorRealism* r) {
  ReadCamera(m.Map("camera"), &r->camera);
  ReadLink(m.Map("command"), &r->command);
  MapReader e = m.Map("encoder");
  e.Number("resolution", &r->encoder.resolution);
  e.Number("noise_stddev", &r->encoder.noise_stddev);
  ReadLink(e.Map("link"), &r->encoder.link);
  e.Finish();
  MapReader i = m.Map("imu");
  i.Number("gyro_bias", &r->imu.gyro_bias);
  i.Number("gyro_noise_stddev", &r->imu.gyro_noise_stddev);
  i.Number("accel_bias", &r->imu.accel_bias);
  i.Number("accel_noise_stddev", &r->imu.accel_noise_stddev);
  ReadLink(i.Map("link"), &r->imu.link);
  i.Finish();
  MapReader t = m.Map("touch");
  ReadLink(t.Map("link"), &r->touch.link);
  t.Finish();
  m.Finish();
}

void ReadSceneRealism(MapReader& m, const std::string& base_dir, SensorRealism* realism,
                      std::vector<std::string>* errors) {
  if (!m.Has("realism")) return;
  const YAML::Node node = m.Child("realism");
  if (node.IsScalar()) {
    RealismLoadResult preset = LoadRealism(RealismSpecFrom(node.as<std::string>(), base_dir));
    for (const std::string& e : preset.errors) errors->push_back("realism: " + e);
    if (preset.realism) *realism = *preset.realism;
  } else {
    ReadRealism(m.Map("realism"), realism);
  }
}

std::string DefaultRealismDir() { return TURF_REALISM_DIR; }

namespace {

// Only blank lines and comments.
bool Blank(const std::string& text) {
  size_t line = 0;
  while (line < text.size()) {
    const size_t end = std::min(text.find('\n', line), text.size());
    const size_t first = text.find_first_not_of(" \t\r", line);
    if (first < end && text[first] != '#') return false;
    line = end + 1;
  }
  return true;
}

}  // namespace

RealismLoadResult ParseRealismYaml(const std::string& yaml_text, const SensorRealism& base) {
  RealismLoadResult result;
  if (yaml_text.size() > kMaxRealismBytes) {
    result.errors.push_back("realism text too large");
    return result;
  }
  try {
    // One document, read as scene files are (a second one, or garbage after `...`, was ignored); a text of only
    // comments and blank lines changes nothing.
    YAML::Node root;
    if (!Blank(yaml_text)) {
      std::optional<YAML::Node> document = yaml::LoadSceneDocument(yaml_text, &result.errors);
      if (!document) return result;
      root = *document;
    }
    SensorRealism realism = base;
    ReadRealism(MapReader(root, "", &result.errors), &realism);
    if (const char* e = CheckRealism(realism); *e != '\0') result.errors.push_back(e);
    if (result.errors.empty()) result.realism = realism;
  } catch (const YAML::Exception& e) {
    result.errors.push_back(fmt::format("malformed realism YAML: {}", e.what()));
  } catch (const std::exception& e) {
    result.errors.push_back(fmt::format("cannot read realism: {}", e.what()));
  }
  return result;
}

std::vector<std::string> RealismPresets(const std::string& dir) {
  std::vector<std::string> names;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec))
    if (entry.path().extension() == ".yaml") names.push_back(entry.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

namespace {

bool IsYamlText(const std::string& spec) {
  return spec.find(':') != std::string::npos || spec.find('{') != std::string::npos;
}

bool IsPath(const std::string& spec) {
  return spec.find('/') != std::string::npos || (spec.size() > 5 && spec.substr(spec.size() - 5) == ".yaml");
}

}  // namespace

std::string RealismSpecFrom(const std::string& spec, const std::string& base_dir) {
  if (IsYamlText(spec) || !IsPath(spec) || base_dir.empty()) return spec;
  const std::filesystem::path p(spec);
  return (p.is_absolute() ? p : std::filesystem::path(base_dir) / p).lexically_normal().string();
}

RealismLoadResult LoadRealism(const std::string& spec, const std::string& dir, bool allow_paths,
                              const SensorRealism& base) {
  if (IsYamlText(spec)) return ParseRealismYaml(spec, base);
  const bool is_path = IsPath(spec);
  if (is_path && !allow_paths) return {std::nullopt, {"a realism file path is not accepted here; name a preset"}};
  const bool plain_name = !is_path && !spec.empty() &&
                          spec.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789_-") == std::string::npos;
  if (!is_path && !plain_name) return {std::nullopt, {fmt::format("not a realism preset name: \"{}\"", spec)}};
  const std::string path = is_path ? spec : dir + "/" + spec + ".yaml";
  std::error_code ec;
  if (!is_path && !std::filesystem::is_regular_file(path, ec))
    return {std::nullopt,
            {fmt::format("no realism preset \"{}\" (presets: {})", spec, fmt::join(RealismPresets(dir), ", "))}};
  std::string text, error;
  if (!ReadTextFile(path, kMaxRealismBytes, &text, &error)) return {std::nullopt, {path + ": " + error}};
  RealismLoadResult result = ParseRealismYaml(text);
  for (std::string& e : result.errors) e = path + ": " + e;
  return result;
}

}  // namespace turf
