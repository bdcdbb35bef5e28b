// `turf` as a user runs it: --help, `turf launch <profile> --print` (one shell
// line per process, with flags every program accepts) and profile errors.
#include <gtest/gtest.h>
#include <unistd.h>

#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "tests/multihost/support/netns.h"
#include "tests/support/process.h"

namespace turf::test {
namespace {

std::string Turf() { return Built("participants/launcher/turf"); }

std::vector<std::string> Lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::vector<std::string> Words(const std::string& line) {
  std::vector<std::string> words;
  std::istringstream in(line);
  for (std::string w; in >> w;) words.push_back(w);
  return words;
}

TEST(LaunchCli, HelpNamesTheSubcommandAndItsOptions) {
  std::string out;
  EXPECT_EQ(RunCommand({Turf(), "--help"}, &out), 0);
  EXPECT_NE(out.find("launch"), std::string::npos) << out;
  EXPECT_EQ(RunCommand({Turf(), "launch", "--help"}, &out), 0);
  for (const char* option : {"--print", "--domain", "--prefix", "--discovery-server", "--start-discovery-server",
                             "--only", "--set", "--bin-dir"})
    EXPECT_NE(out.find(option), std::string::npos) << option;
  EXPECT_NE(RunCommand({Turf()}, &out), 0) << "a subcommand is required";
}

// Each printed line runs a built program with options it knows.
void ExpectRunnable(const std::vector<std::string>& lines) {
  for (const std::string& line : lines) {
    std::vector<std::string> words = Words(line);
    while (!words.empty() && words[0].find('=') != std::string::npos) words.erase(words.begin());
    ASSERT_FALSE(words.empty()) << line;
    ASSERT_EQ(access(words[0].c_str(), X_OK), 0) << words[0];
    std::string help;
    const bool system_tool = words[0].rfind(TURF_BINARY_DIR, 0) != 0;
    RunCommand({words[0], system_tool ? "-h" : "--help"}, &help);
    for (size_t i = 1; i < words.size(); ++i) {
      if (words[i][0] != '-') continue;
      const std::regex known("(^|[\\s,])" + words[i] + "[\\s=]");
      EXPECT_TRUE(std::regex_search(help, known)) << words[0] << " does not know " << words[i];
    }
  }
}

TEST(LaunchCli, PrintGivesOneRunnableLinePerProcess) {
  for (const char* profile : {"ssl_div_a", "ssl_div_b"}) {
    std::string out;
    ASSERT_EQ(RunCommand({Turf(), "launch", profile, "--print"}, &out), 0) << out;
    const std::vector<std::string> lines = Lines(out);
    ASSERT_EQ(lines.size(), 5u) << out;  // turf-sim, three bridges, the viewer (localhost only)
    EXPECT_NE(lines[4].find("/turf-viewer --domain 0 --prefix turf --listen 127.0.0.1 --port 8080"), std::string::npos)
        << lines[4];
    EXPECT_NE(lines[0].find("/turf-sim --scene "), std::string::npos) << lines[0];
    EXPECT_NE(lines[0].find(std::string("configs/scenes/") + profile + ".yaml"), std::string::npos) << lines[0];
    for (const std::string& line : lines) EXPECT_NE(line.find(" --domain 0 --prefix turf"), std::string::npos);
    ExpectRunnable(lines);
  }
}

TEST(LaunchCli, PrintSimSparkAndItsSyncMode) {
  std::string out;
  ASSERT_EQ(RunCommand({Turf(), "launch", "simspark", "--print"}, &out), 0) << out;
  std::vector<std::string> lines = Lines(out);
  ASSERT_EQ(lines.size(), 3u) << out;
  EXPECT_NE(lines[0].find("/turf-sim --scene "), std::string::npos) << lines[0];
  EXPECT_NE(lines[0].find("configs/scenes/simspark_match.yaml --domain 0 --prefix turf"), std::string::npos);
  EXPECT_NE(lines[1].find("/turf-simspark-bridge --domain 0 --prefix turf --listen 0.0.0.0 --agent-port 3100 "
                          "--monitor-port 3200"),
            std::string::npos)
      << lines[1];
  EXPECT_EQ(lines[1].find("--sync"), std::string::npos) << "real time by default";
  ExpectRunnable(lines);

  ASSERT_EQ(
      RunCommand({Turf(), "launch", "simspark", "--print", "--set", "simspark.sync=true", "--only", "simspark"}, &out),
      0)
      << out;
  lines = Lines(out);
  ASSERT_EQ(lines.size(), 1u) << out;
  EXPECT_NE(lines[0].find("turf-simspark-bridge "), std::string::npos) << lines[0];
  EXPECT_NE(lines[0].find(" --sync"), std::string::npos) << lines[0];
  ExpectRunnable(lines);

  ASSERT_EQ(RunCommand({Turf(), "launch", "simspark", "--print", "--only", "sim"}, &out), 0) << out;
  lines = Lines(out);
  ASSERT_EQ(lines.size(), 1u) << out;
  EXPECT_NE(lines[0].find("/turf-sim "), std::string::npos) << lines[0];

  // Legged scenes model encoders and IMU: the realism preset reaches turf-sim.
  ASSERT_EQ(RunCommand({Turf(), "launch", "simspark", "--print", "--only", "sim", "--realism", "harsh"}, &out), 0);
  EXPECT_NE(out.find("--realism harsh"), std::string::npos) << out;
  EXPECT_EQ(RunCommand({Turf(), "launch", "simspark", "--print", "--only", "grsim"}, &out), 2);
  EXPECT_NE(out.find("sim, simspark"), std::string::npos) << out;
}

// The SSL simulation protocol served in turf-sim instead of the separate bridge (README, turf-sim --simproto).
TEST(LaunchCli, PrintSimprotoInTurfSim) {
  std::string out;
  ASSERT_EQ(RunCommand({Turf(), "launch", "ssl_div_a", "--print", "--only", "sim,grsim,vision", "--set",
                        "sim.simproto=0.0.0.0"},
                       &out),
            0)
      << out;
  const std::vector<std::string> lines = Lines(out);
  ASSERT_EQ(lines.size(), 3u) << out;
  EXPECT_NE(lines[0].find("/turf-sim "), std::string::npos) << lines[0];
  EXPECT_NE(lines[0].find(" --simproto 0.0.0.0"), std::string::npos) << lines[0];
  EXPECT_EQ(out.find("turf-simproto-bridge"), std::string::npos) << out;
  ExpectRunnable(lines);
}

TEST(LaunchCli, PrintWithOverridesAndADiscoveryServer) {
  std::string out;
  ASSERT_EQ(RunCommand({Turf(), "launch", "ssl_div_a", "--print", "--domain", "42", "--prefix", "field2",
                        "--discovery-server", "192.168.7.1:11811", "--start-discovery-server", "--only",
                        "discovery,sim,vision", "--set", "vision.port=10006"},
                       &out),
            0)
      << out;
  const std::vector<std::string> lines = Lines(out);
  ASSERT_EQ(lines.size(), 3u) << out;
  EXPECT_NE(lines[0].find("fast-discovery-server -i 0 -l 192.168.7.1 -p 11811"), std::string::npos) << lines[0];
  for (size_t i = 1; i < lines.size(); ++i) {
    EXPECT_EQ(lines[i].rfind("ROS_DISCOVERY_SERVER=192.168.7.1:11811 ", 0), 0u) << lines[i];
    EXPECT_NE(lines[i].find(" --domain 42 --prefix field2"), std::string::npos) << lines[i];
  }
  EXPECT_NE(lines[2].find("--port 10006"), std::string::npos) << lines[2];
  ExpectRunnable(lines);
}

// The physics host of a split match: --start-discovery-server runs the server
// there even with --only sim.
TEST(LaunchCli, StartDiscoveryServerRunsItWhateverOnlySays) {
  std::string out;
  ASSERT_EQ(RunCommand({Turf(), "launch", "ssl_div_b", "--print", "--only", "sim", "--discovery-server",
                        "10.0.0.1:11811", "--start-discovery-server"},
                       &out),
            0)
      << out;
  const std::vector<std::string> lines = Lines(out);
  ASSERT_EQ(lines.size(), 2u) << out;
  EXPECT_NE(lines[0].find("fast-discovery-server"), std::string::npos);
  EXPECT_NE(lines[1].find("turf-sim"), std::string::npos);
}

TEST(LaunchCli, ProfileErrorsNameTheKeyAndExitWith2) {
  const std::string path = std::string(TURF_BINARY_DIR) + "/tests/bad_profile_" + std::to_string(getpid()) + ".yaml";
  std::ofstream(path) << "scene: " << TURF_SOURCE_DIR << "/configs/scenes/ssl_div_a.yaml\ndomian: 3\n";
  std::string out;
  EXPECT_EQ(RunCommand({Turf(), "launch", path, "--print"}, &out), 2);
  EXPECT_NE(out.find("domian: unknown key (did you mean domain?)"), std::string::npos) << out;
  EXPECT_EQ(RunCommand({Turf(), "launch", "ssl_div_a", "--print", "--set", "radio.port=1"}, &out), 2);
  EXPECT_NE(out.find("no process named 'radio'"), std::string::npos) << out;
  EXPECT_EQ(RunCommand({Turf(), "launch", "no_such_league"}, &out), 2);
  EXPECT_NE(out.find("ssl_div_a"), std::string::npos) << out;
  std::remove(path.c_str());
  // A refused value says what is allowed in one short line, and exits 2 (CLI11's own check printed 310 digits).
  EXPECT_EQ(RunCommand({Turf(), "launch", "ssl_div_a", "--grace", "0"}, &out), 2);
  EXPECT_NE(out.find("--grace: '0' is not a number > 0"), std::string::npos) << out;
  EXPECT_LT(out.size(), 200u) << out;
  EXPECT_EQ(RunCommand({Built("participants/sim/turf-sim"), "--duration", "-1"}, &out), 2);
  EXPECT_NE(out.find("--duration: '-1' is not a number >= 0"), std::string::npos) << out;
  EXPECT_LT(out.size(), 200u) << out;
  // A mistyped flag is refused before anything starts (each program's --help is the list), not retried.
  EXPECT_EQ(RunCommand({Turf(), "launch", "ssl_div_a", "--domain", "231", "--set", "sim.sped=2"}, &out), 2);
  EXPECT_NE(out.find("sim: turf-sim has no flag --sped"), std::string::npos) << out;
  EXPECT_EQ(out.find("started"), std::string::npos) << "nothing started: " << out;
}

}  // namespace
}  // namespace turf::test
