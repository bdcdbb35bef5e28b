#include "participants/launcher/launch_profile.h"

#include <arpa/inet.h>
#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <optional>
#include <set>

#include "dds/topic_prefix.h"
#include "loader/realism_yaml.h"
#include "loader/text_file.h"
#include "loader/yaml_reader.h"
#include "participants/launcher/programs.h"

namespace turf::launch {

namespace fs = std::filesystem;
using yaml::Errors;
using yaml::MapReader;

namespace {

// Flags that come from top-level keys, per process ("*": every process).
bool Reserved(const std::string& process, const std::string& flag) {
  static const std::set<std::string> every = {"domain", "prefix", "qos"};
  static const std::set<std::string> sim = {"scene", "realism"};
  return every.count(flag) != 0 || (process == "sim" && sim.count(flag) != 0);
}

std::string Absolute(const std::string& path, const std::string& base_dir) {
  const fs::path p(path);
  return (p.is_absolute() ? p : fs::path(base_dir) / p).lexically_normal().string();
}

// A regular file there: false, not an exception, for a path the system refuses (too long, a loop, no access).
bool IsFile(const std::string& path) {
  std::error_code ec;
  return fs::is_regular_file(path, ec);
}

// One flag value: scalar, bool or list of scalars.
bool ReadFlagValue(const YAML::Node& node, const std::string& path, Errors* errors, Flag* flag) {
  if (node.IsNull()) {
    errors->push_back(yaml::Message(path, node, "no value given (true for a switch)"));
    return false;
  }
  if (node.IsScalar()) {
    const bool quoted = node.Tag() == "!" || node.Tag() == "tag:yaml.org,2002:str";
    const std::string& text = node.Scalar();
    if (!quoted && (text == "true" || text == "false")) {
      flag->bare = true;
      flag->value = text;  // "false": left out when the command is built
      return true;
    }
    flag->value = text;
    return true;
  }
  if (node.IsSequence() && node.size() > 0) {
    std::vector<std::string> items;
    for (size_t i = 0; i < node.size(); ++i) {
      std::string item;
      if (!yaml::ReadString(node[i], fmt::format("{}[{}]", path, i), errors, &item)) return false;
      items.push_back(item);
    }
    flag->value = fmt::format("{}", fmt::join(items, ","));
    return true;
  }
  errors->push_back(yaml::Message(path, node, "expected a value, true/false or a list of values"));
  return false;
}

// A map of flags for `process`, in the order written.
void ReadFlags(const YAML::Node& node, const std::string& path, const std::string& process, Errors* errors,
               std::vector<Flag>* flags) {
  MapReader reader(node, path, errors);  // reports a non-map and duplicate keys
  if (!node.IsMap()) return;
  std::set<std::string> seen;
  for (const auto& pair : node) {
    if (!pair.first.IsScalar()) continue;
    const std::string name = pair.first.Scalar();
    const std::string flag_path = reader.PathOf(name);
    reader.Child(name);  // known
    if (!seen.insert(name).second) continue;
    if (!ValidFlagName(name)) {
      errors->push_back(yaml::Message(flag_path, pair.first, "not a flag name (a long option without its dashes)"));
      continue;
    }
    if (Reserved(process, name)) {
      errors->push_back(yaml::Message(flag_path, pair.first, "set by the profile's top-level key of that name"));
      continue;
    }
    Flag flag{name, "", false};
    if (ReadFlagValue(pair.second, flag_path, errors, &flag)) {
      if (!(flag.bare && flag.value == "false")) flags->push_back(flag);
    }
  }
  reader.Finish();
}

// `legged`: the scene's kind, unknown (nullopt) when the scene did not load.
void ReadBridges(const YAML::Node& node, std::optional<bool> legged, Errors* errors,
                 std::vector<ProcessSpec>* bridges) {
  MapReader reader(node, "bridges", errors);
  if (!node.IsMap()) return;
  std::set<std::string> seen;
  for (const auto& pair : node) {
    if (!pair.first.IsScalar()) continue;
    const std::string name = pair.first.Scalar();
    const Program* program = FindProgram(name);
    if (program == nullptr || !IsBridge(name)) continue;  // Finish() reports it
    reader.Child(name);
    if (!seen.insert(name).second) continue;
    if (legged && program->scenes != Scenes::kAny && (program->scenes == Scenes::kLegged) != *legged) {
      errors->push_back(
          yaml::Message(reader.PathOf(name), pair.first,
                        fmt::format("{} works with {} scenes, the profile's scene is {}", program->binary,
                                    *legged ? "SSL" : "legged (kind: legged)", *legged ? "legged" : "an SSL scene")));
    }
    ProcessSpec spec{name, {}};
    ReadFlags(pair.second, reader.PathOf(name), name, errors, &spec.flags);
    bridges->push_back(spec);
  }
  std::vector<std::string> names;
  for (const Program& p : kPrograms) {
    if (IsBridge(p.name)) names.emplace_back(p.name);
  }
  const size_t before = errors->size();
  reader.Finish();
  for (size_t i = before; i < errors->size(); ++i) {
    (*errors)[i] += fmt::format(" (bridges: {})", fmt::join(names, ", "));
  }
}

void ReadRestart(MapReader m, RestartPolicy* r) {
  if (m.Int("max_restarts", &r->max_restarts) && r->max_restarts < 0) m.Fail("max_restarts", "must be >= 0");
  const std::string at_most = fmt::format("must be <= {} (s)", kMaxLaunchSeconds);
  if (m.Number("backoff_initial", &r->backoff_initial) && r->backoff_initial < 0)
    m.Fail("backoff_initial", "must be >= 0");
  if (r->backoff_initial > kMaxLaunchSeconds) m.Fail("backoff_initial", at_most);
  if (m.Number("backoff_max", &r->backoff_max) && r->backoff_max < r->backoff_initial)
    m.Fail("backoff_max", "must be >= backoff_initial");
  if (r->backoff_max > kMaxLaunchSeconds) m.Fail("backoff_max", at_most);
  if (m.Number("stable_after", &r->stable_after) && r->stable_after < 0) m.Fail("stable_after", "must be >= 0");
  if (r->stable_after > kMaxLaunchSeconds) m.Fail("stable_after", at_most);
  m.Finish();
}

void ReadDiscovery(MapReader m, DiscoverySpec* d) {
  std::string host;
  int port = 0;
  if (m.String("server", &d->server) && !ParseHostPort(d->server, &host, &port))
    m.Fail("server", fmt::format("expected HOST:PORT (e.g. 192.168.1.10:11811), got \"{}\"", d->server));
  m.Bool("start", &d->start);
  if (d->start && d->server.empty()) m.Fail("start", "needs discovery.server (the address it listens on)");
  m.Finish();
}

}  // namespace

bool ParseHostPort(const std::string& text, std::string* host, int* port) {
  const size_t colon = text.rfind(':');
  if (colon == std::string::npos || colon == 0 || colon + 1 == text.size()) return false;
  const std::string h = text.substr(0, colon);
  const std::string p = text.substr(colon + 1);
  if (!std::all_of(p.begin(), p.end(), [](unsigned char c) { return std::isdigit(c); }) || p.size() > 5) return false;
  const int n = std::stoi(p);
  if (n < 1 || n > 65535) return false;
  const bool name_chars =
      std::all_of(h.begin(), h.end(), [](unsigned char c) { return std::isalnum(c) || c == '-' || c == '.'; });
  if (!name_chars) return false;
  // All digits and dots: must be a real dotted IPv4 address.
  if (h.find_first_not_of("0123456789.") == std::string::npos) {
    in_addr addr{};
    if (inet_pton(AF_INET, h.c_str(), &addr) != 1) return false;
  }
  *host = h;
  *port = n;
  return true;
}

bool ValidFlagName(const std::string& name) {
  return !name.empty() && std::islower(static_cast<unsigned char>(name[0])) &&
         std::all_of(name.begin(), name.end(),
                     [](unsigned char c) { return std::islower(c) || std::isdigit(c) || c == '-'; });
}

// `turf launch --scene`: another scene of the profile's kind (its programs and flags are for that kind).
void OverrideScene(const std::string& scene, LaunchProfile* p, Errors* errors) {
  const std::string path = fs::absolute(scene).lexically_normal().string();
  if (!IsFile(path)) {
    errors->push_back(fmt::format("--scene: no such file: {}", path));
    return;
  }
  const auto kind = [](bool legged) { return legged ? "a legged scene" : "an SSL scene"; };
  if (!p->scene.empty() && IsLeggedScene(p->scene) != IsLeggedScene(path)) {
    errors->push_back(fmt::format("--scene: {} is {}; this profile runs {}", path, kind(IsLeggedScene(path)),
                                  kind(IsLeggedScene(p->scene))));
    return;
  }
  p->scene = path;
}

ProfileLoadResult ParseLaunchProfile(const std::string& yaml_text, const std::string& base_dir,
                                     const std::string& scene) {
  ProfileLoadResult result;
  Errors& errors = result.errors;
  YAML::Node root;
  try {
    root = YAML::Load(yaml_text);
  } catch (const YAML::Exception& e) {
    errors.push_back(fmt::format("not valid YAML: {}", e.what()));
    return result;
  }
  LaunchProfile p;
  MapReader m(root, "", &errors);
  m.String("name", &p.name);
  if (!m.String("scene", &p.scene)) {
    if (!m.Has("scene")) m.Fail("scene", "missing: the scene file turf-sim loads");
  } else {
    p.scene = Absolute(p.scene, base_dir);
    if (!IsFile(p.scene)) m.Fail("scene", fmt::format("no such file: {}", p.scene));
  }
  if (!scene.empty()) OverrideScene(scene, &p, &errors);
  if (!p.scene.empty()) p.legged = IsLeggedScene(p.scene);
  if (m.String("realism", &p.realism)) {
    p.realism = RealismSpecFrom(p.realism, base_dir);
    const RealismLoadResult realism = LoadRealism(p.realism);
    if (!realism.realism) {
      m.Fail("realism",
             fmt::format("not a preset of configs/realism/ or a realism file: {}", fmt::join(realism.errors, "; ")));
    }
  }
  if (m.Int("domain", &p.domain) && (p.domain < 0 || p.domain > 232)) m.Fail("domain", "must be 0..232");
  if (m.String("prefix", &p.prefix) && !dds::ValidTopicPrefix(p.prefix)) m.Fail("prefix", dds::kTopicPrefixRule);
  if (m.String("qos", &p.qos)) {
    p.qos = Absolute(p.qos, base_dir);
    if (!IsFile(p.qos)) m.Fail("qos", fmt::format("no such file: {}", p.qos));
  }
  ReadDiscovery(m.Map("discovery"), &p.discovery);
  ReadFlags(m.Child("sim"), "sim", "sim", &errors, &p.sim.flags);
  const bool scene_loads = !p.scene.empty() && IsFile(p.scene);
  ReadBridges(m.Child("bridges"), scene_loads ? std::optional<bool>(p.legged) : std::nullopt, &errors, &p.bridges);
  ReadRestart(m.Map("restart"), &p.restart);
  if (m.Number("stop_grace", &p.stop_grace) && !(p.stop_grace > 0 && p.stop_grace <= kMaxLaunchSeconds))
    m.Fail("stop_grace", fmt::format("must be > 0 and <= {} (s)", kMaxLaunchSeconds));
  m.Finish();
  if (errors.empty()) result.profile = std::move(p);
  return result;
}

ProfileLoadResult LoadLaunchProfile(const std::string& name_or_path, const std::string& dir, const std::string& scene) {
  fs::path path(name_or_path);
  const bool is_name = name_or_path.find('/') == std::string::npos && path.extension() != ".yaml";
  if (is_name) path = fs::path(dir) / (name_or_path + ".yaml");
  ProfileLoadResult result;
  std::string text, error;
  if (!ReadTextFile(path.string(), kMaxProfileBytes, &text, &error)) {
    std::string known;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(dir, ec)) {
      if (entry.path().extension() == ".yaml") known += (known.empty() ? "" : ", ") + entry.path().stem().string();
    }
    result.errors.push_back(fmt::format("{}: cannot read the profile: {}{}", path.string(), error,
                                        is_name ? fmt::format(" (profiles in {}: {})", dir, known) : ""));
    return result;
  }
  const std::string base = fs::absolute(path).parent_path().string();
  result = ParseLaunchProfile(text, base, scene);
  for (std::string& e : result.errors) e = fmt::format("{}: {}", path.string(), e);
  if (result.profile) {
    result.profile->path = fs::absolute(path).lexically_normal().string();
    if (result.profile->name.empty()) result.profile->name = path.stem().string();
  }
  return result;
}

bool IsLeggedScene(const std::string& path) {
  try {
    std::string text, error;
    if (!ReadTextFile(path, 1 << 20, &text, &error)) return false;
    const YAML::Node root = YAML::Load(text);
    return root.IsMap() && root["kind"] && root["kind"].IsScalar() && root["kind"].Scalar() == "legged";
  } catch (const std::exception&) {
    return false;
  }
}

std::string DefaultProfileDir() { return TURF_LAUNCH_PROFILE_DIR; }

}  // namespace turf::launch
