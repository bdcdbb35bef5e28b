// docker/Dockerfile and docker/compose.yaml, checked without a Docker engine:
// the image is built by the project's own scripts (no second package list),
// every command the compose file runs is a program of this build (on the
// image's PATH) or a tool of a package scripts/setup.sh installs, its flags
// exist, and the published ports are the participants' defaults.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "participants/launcher/programs.h"
#include "tests/multihost/support/netns.h"

namespace turf::test {
namespace {

const std::string kSource = TURF_SOURCE_DIR;

std::string Read(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Dockerfile instructions, continuation lines joined, comments dropped.
std::vector<std::string> Instructions() {
  std::vector<std::string> out;
  std::istringstream lines(Read(kSource + "/docker/Dockerfile"));
  std::string current;
  for (std::string line; std::getline(lines, line);) {
    if (current.empty() && (line.empty() || line[0] == '#')) continue;
    const bool more = !line.empty() && line.back() == '\\';
    current += more ? line.substr(0, line.size() - 1) : line;
    if (!more) {
      out.push_back(current);
      current.clear();
    }
  }
  return out;
}

// The PACKAGES array of scripts/setup.sh.
std::set<std::string> SetupPackages() {
  const std::string text = Read(kSource + "/scripts/setup.sh");
  const size_t begin = text.find("PACKAGES=(");
  const size_t end = text.find(')', begin);
  std::set<std::string> packages;
  std::istringstream body(text.substr(begin + 10, end - begin - 10));
  for (std::string line; std::getline(body, line);) {
    std::istringstream words(line.substr(0, line.find('#')));
    for (std::string w; words >> w;) packages.insert(w);
  }
  return packages;
}

// Option names and their defaults in a program's --help.
struct Help {
  std::set<std::string> options;
  std::map<std::string, std::string> defaults;
};

Help HelpOf(const std::string& binary, const std::string& flag = "--help") {
  std::string text;
  RunCommand({binary, flag}, &text);
  Help help;
  const std::regex option(R"((?:^|[\s,])(--?[a-zA-Z][a-zA-Z0-9-]*))");
  for (std::sregex_iterator it(text.begin(), text.end(), option), end; it != end; ++it) help.options.insert((*it)[1]);
  const std::regex with_default(R"((--[a-z0-9-]+) [A-Z]+[^\n=]*=(\S+))");
  for (std::sregex_iterator it(text.begin(), text.end(), with_default), end; it != end; ++it)
    help.defaults[(*it)[1]] = (*it)[2];
  return help;
}

// A built program: its executable in this build tree.
std::string BuiltProgram(const std::string& binary) {
  for (const launch::Program& p : launch::kPrograms) {
    if (p.binary == binary && !p.build_dir.empty())
      return std::string(TURF_BINARY_DIR) + "/participants/" + std::string(p.build_dir) + "/" + binary;
  }
  if (binary == "turf") return std::string(TURF_BINARY_DIR) + "/participants/launcher/turf";
  return "";
}

// System tools compose may run, with the Debian package that has them.
const std::map<std::string, std::string> kTools = {{"fast-discovery-server", "fastdds-tools"}};

TEST(DockerFiles, DockerfileUsesTheProjectScripts) {
  const std::vector<std::string> ins = Instructions();
  ASSERT_FALSE(ins.empty());
  EXPECT_EQ(ins[0], "FROM debian:12");
  bool copy = false, setup = false, build = false;
  for (const std::string& i : ins) {
    copy = copy || i.rfind("COPY . ", 0) == 0;
    setup = setup || (i.rfind("RUN ", 0) == 0 && i.find("scripts/setup.sh") != std::string::npos);
    build = build || (i.rfind("RUN ", 0) == 0 && i.find("scripts/build.sh") != std::string::npos);
    EXPECT_EQ(i.find("apt-get install"), std::string::npos) << "packages are listed in scripts/setup.sh only: " << i;
    EXPECT_EQ(i.find("apt install"), std::string::npos) << i;
  }
  EXPECT_TRUE(copy && setup && build);
  std::ifstream ignore(kSource + "/.dockerignore");
  EXPECT_TRUE(ignore.good()) << "build trees must stay out of the build context";
}

// The image's PATH: every /turf/build/... entry exists in this build tree.
std::set<std::string> ImagePath() {
  std::set<std::string> dirs;
  for (const std::string& i : Instructions()) {
    if (i.rfind("ENV PATH=", 0) != 0) continue;
    std::istringstream entries(i.substr(9));
    for (std::string dir; std::getline(entries, dir, ':');) {
      if (dir.rfind("/turf/build/", 0) == 0) dirs.insert(dir.substr(12));
    }
  }
  return dirs;
}

TEST(DockerFiles, ComposeRunsBuiltProgramsWithRealFlagsAndDefaultPorts) {
  const YAML::Node compose = YAML::LoadFile(kSource + "/docker/compose.yaml");
  const YAML::Node services = compose["services"];
  ASSERT_TRUE(services.IsMap());
  std::set<std::string> names;
  for (const auto& s : services) names.insert(s.first.as<std::string>());
  EXPECT_EQ(names, (std::set<std::string>{"discovery", "sim", "grsim", "vision", "simproto"}));
  const std::set<std::string> path = ImagePath();
  const std::set<std::string> packages = SetupPackages();
  int discovery_port = 0;
  std::map<std::string, std::vector<std::string>> commands;

  for (const auto& s : services) {
    const std::string name = s.first.as<std::string>();
    const YAML::Node service = s.second;
    EXPECT_EQ(service["image"].as<std::string>(), "turf") << name;
    EXPECT_TRUE(service["networks"].IsSequence()) << name;
    const std::vector<std::string> command = service["command"].as<std::vector<std::string>>();
    ASSERT_FALSE(command.empty()) << name;
    commands[name] = command;
    const std::string& program = command[0];
    Help help;
    const std::string built = BuiltProgram(program);
    if (!built.empty()) {
      // A program of this build, on the image's PATH.
      const std::string dir = built.substr(std::string(TURF_BINARY_DIR).size() + 1);
      EXPECT_TRUE(path.count(dir.substr(0, dir.rfind('/')))) << program << " is not on the image's PATH";
      help = HelpOf(built);
      ASSERT_FALSE(help.options.empty()) << built << " --help printed no options";
    } else {
      ASSERT_TRUE(kTools.count(program)) << name << ": " << program << " is neither built here nor a known tool";
      EXPECT_TRUE(packages.count(kTools.at(program))) << kTools.at(program) << " is not in scripts/setup.sh";
      help = HelpOf(program, "-h");
    }
    for (size_t i = 1; i < command.size(); ++i) {
      if (command[i][0] != '-') continue;
      EXPECT_TRUE(help.options.count(command[i])) << name << ": " << program << " has no option " << command[i];
      if (command[i] == "-p" && name == "discovery") discovery_port = std::stoi(command[i + 1]);
    }
    // Published ports: the same number outside and inside, each one a port
    // the service listens on by default.
    std::set<std::string> listened;
    for (const auto& [option, value] : help.defaults) {
      if (option.find("port") != std::string::npos && option.find("status") == std::string::npos)
        listened.insert(value);
    }
    if (name == "discovery") listened.insert(std::to_string(discovery_port));
    for (const YAML::Node& p : service["ports"]) {
      std::smatch m;
      const std::string spec = p.as<std::string>();
      ASSERT_TRUE(std::regex_match(spec, m, std::regex(R"((\d+)(?:-(\d+))?:(\d+)(?:-(\d+))?/udp)"))) << spec;
      EXPECT_EQ(m[1], m[3]) << spec;
      EXPECT_EQ(m[2], m[4]) << spec;
      const int first = std::stoi(m[1]), last = m[2].matched ? std::stoi(m[2]) : first;
      for (int port = first; port <= last; ++port)
        EXPECT_TRUE(listened.count(std::to_string(port))) << name << " publishes " << port << ", not its default";
    }
    // Every DDS participant finds the others through the discovery service.
    if (name != "discovery") {
      EXPECT_EQ(service["environment"]["ROS_DISCOVERY_SERVER"].as<std::string>(),
                "discovery:" + std::to_string(discovery_port))
          << name;
    }
  }
  // The SSL ports a team needs are published.
  const std::string text = Read(kSource + "/docker/compose.yaml");
  EXPECT_NE(text.find("\"20011:20011/udp\""), std::string::npos);
  EXPECT_NE(text.find("\"10300-10302:10300-10302/udp\""), std::string::npos);
  // The match is the default profile's: same scene and realism.
  const std::vector<std::string>& sim = commands["sim"];
  const std::string profile = Read(kSource + "/configs/launch/ssl_div_a.yaml");
  for (const char* flag : {"--scene", "--realism"}) {
    const auto it = std::find(sim.begin(), sim.end(), flag);
    ASSERT_NE(it, sim.end()) << flag;
    const std::string value = *(it + 1);
    const std::string tail = value.substr(value.rfind('/') + 1);
    EXPECT_NE(profile.find(tail), std::string::npos) << flag << " " << value << " differs from ssl_div_a";
  }
}

}  // namespace
}  // namespace turf::test
