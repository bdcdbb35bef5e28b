// League launch profiles: the shipped ones load, bad ones fail with errors
// that name the key, and plans carry the overrides into every command.
#include "participants/launcher/launch_profile.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "participants/launcher/launch_plan.h"
#include "participants/launcher/programs.h"

namespace turf::launch {
namespace {

namespace fs = std::filesystem;

const std::string kScenes = std::string(TURF_SOURCE_DIR) + "/configs/scenes";
// Where `turf` is, so that plans find the executables next to it.
const std::string kLauncherDir = std::string(TURF_BINARY_DIR) + "/participants/launcher";

ProfileLoadResult Parse(const std::string& text) { return ParseLaunchProfile(text, kScenes); }

// The single error of `text`, which must contain `key` and `what`.
void ExpectError(const std::string& text, const std::string& key, const std::string& what) {
  const ProfileLoadResult r = Parse(text);
  EXPECT_FALSE(r.profile.has_value()) << text;
  ASSERT_EQ(r.errors.size(), 1u) << text << "\n" << (r.errors.empty() ? "" : r.errors[0]);
  EXPECT_EQ(r.errors[0].rfind(key + ":", 0), 0u) << r.errors[0];
  EXPECT_NE(r.errors[0].find(what), std::string::npos) << r.errors[0];
}

std::string Args(const ProcessCommand& c) {
  std::string s;
  for (size_t i = 1; i < c.argv.size(); ++i) s += c.argv[i] + " ";
  return s;
}

TEST(LaunchProfile, ShippedProfilesLoad) {
  int count = 0;
  for (const auto& entry : fs::directory_iterator(DefaultProfileDir())) {
    if (entry.path().extension() != ".yaml") continue;
    ++count;
    const ProfileLoadResult r = LoadLaunchProfile(entry.path().string(), DefaultProfileDir());
    ASSERT_TRUE(r.profile.has_value()) << entry.path() << ": " << (r.errors.empty() ? "" : r.errors[0]);
    EXPECT_EQ(r.profile->name, entry.path().stem().string());
    EXPECT_TRUE(fs::is_regular_file(r.profile->scene));
    if (!r.profile->legged) {
      EXPECT_FALSE(r.profile->realism.empty()) << "an SSL profile names its realism preset";
    }
    EXPECT_FALSE(r.profile->bridges.empty());
  }
  EXPECT_GE(count, 3);
  const ProfileLoadResult a = LoadLaunchProfile("ssl_div_a", DefaultProfileDir());
  ASSERT_TRUE(a.profile.has_value());
  EXPECT_EQ(fs::path(a.profile->scene).filename(), "ssl_div_a.yaml");
  ASSERT_EQ(a.profile->bridges.size(), 4u);
  EXPECT_EQ(a.profile->bridges[0].name, "grsim");
  EXPECT_EQ(a.profile->bridges[1].name, "vision");
  EXPECT_EQ(a.profile->bridges[2].name, "simproto");
  EXPECT_EQ(a.profile->bridges[3].name, "viewer");  // the default match shows itself
  const ProfileLoadResult b = LoadLaunchProfile("ssl_div_b", DefaultProfileDir());
  ASSERT_TRUE(b.profile.has_value());
  EXPECT_EQ(fs::path(b.profile->scene).filename(), "ssl_div_b.yaml");
}

TEST(LaunchProfile, SimSparkRunsTheLeggedSceneAndTheBridge) {
  const ProfileLoadResult r = LoadLaunchProfile("simspark", DefaultProfileDir());
  ASSERT_TRUE(r.profile.has_value()) << r.errors[0];
  const LaunchProfile& p = *r.profile;
  EXPECT_EQ(fs::path(p.scene).filename(), "simspark_match.yaml");
  EXPECT_TRUE(p.legged);
  EXPECT_TRUE(p.realism.empty());
  ASSERT_EQ(p.sim.flags.size(), 1u) << "the bridge steps turf-sim: no speed";
  EXPECT_EQ(p.sim.flags[0].name, "lockstep") << "the bridge is the clock from the first frame";
  ASSERT_EQ(p.bridges.size(), 2u);
  EXPECT_EQ(p.bridges[0].name, "simspark");
  EXPECT_EQ(p.bridges[1].name, "viewer");
  EXPECT_FALSE(IsLeggedScene(kScenes + "/ssl_div_a.yaml"));
  EXPECT_FALSE(IsLeggedScene(kScenes + "/nowhere.yaml"));
}

TEST(LaunchProfile, UnknownProfileNamesTheKnownOnes) {
  const ProfileLoadResult r = LoadLaunchProfile("ssl_div_z", DefaultProfileDir());
  ASSERT_EQ(r.errors.size(), 1u);
  EXPECT_NE(r.errors[0].find("ssl_div_a"), std::string::npos) << r.errors[0];
}

// A profile is read with a size cap, and only from a regular file (/dev/zero was read until memory ran out).
TEST(LaunchProfile, ADeviceOrAnOversizedFileIsNoProfile) {
  const ProfileLoadResult zero = LoadLaunchProfile("/dev/zero", DefaultProfileDir());
  EXPECT_FALSE(zero.profile);
  ASSERT_FALSE(zero.errors.empty());
  EXPECT_NE(zero.errors[0].find("cannot read the profile"), std::string::npos) << zero.errors[0];
  const std::string big = std::string(::testing::TempDir()) + "/big_profile.yaml";
  {
    std::ofstream out(big);
    out << "scene: ssl_div_a.yaml\n# " << std::string(kMaxProfileBytes, 'x') << "\n";
  }
  const ProfileLoadResult large = LoadLaunchProfile(big, DefaultProfileDir());
  std::remove(big.c_str());
  EXPECT_FALSE(large.profile);
  ASSERT_FALSE(large.errors.empty());
  EXPECT_NE(large.errors[0].find("too large"), std::string::npos) << large.errors[0];
}

TEST(LaunchProfile, FlagsKeepTheirOrderAndForm) {
  const ProfileLoadResult r = Parse(
      "scene: ssl_div_b.yaml\n"
      "sim: {speed: max, paused: true, lockstep: false}\n"
      "bridges:\n"
      "  vision: {tracked: true, port: 10006, address: '224.5.23.2'}\n"
      "  grsim: {wheel-order: [4, 3, 2, 1]}\n");
  ASSERT_TRUE(r.profile.has_value()) << r.errors[0];
  const LaunchProfile& p = *r.profile;
  EXPECT_EQ(p.domain, 0);
  EXPECT_EQ(p.prefix, "turf");
  ASSERT_EQ(p.sim.flags.size(), 2u);  // lockstep: false is left out
  EXPECT_EQ(p.sim.flags[1].name, "paused");
  EXPECT_TRUE(p.sim.flags[1].bare);
  ASSERT_EQ(p.bridges.size(), 2u);
  EXPECT_EQ(p.bridges[0].name, "vision");
  EXPECT_EQ(p.bridges[0].flags[2].value, "224.5.23.2");
  EXPECT_EQ(p.bridges[1].flags[0].value, "4,3,2,1");
}

TEST(LaunchProfile, ErrorsNameTheKey) {
  ExpectError("bridges: {}\n", "scene", "missing");
  ExpectError("scene: nowhere.yaml\n", "scene", "no such file");
  // A path the system refuses to look at (a name over NAME_MAX) is an error too, not an exception
  // (fuzz_launch_profile).
  ExpectError("scene: " + std::string(5000, 'a') + "\n", "scene", "no such file");
  ExpectError("scene: ssl_div_a.yaml\nqos: " + std::string(5000, 'q') + "\n", "qos", "no such file");
  ExpectError("scene: ssl_div_a.yaml\ndomain: 300\n", "domain", "0..232");
  ExpectError("scene: ssl_div_a.yaml\ndomain: two\n", "domain", "integer");
  ExpectError("scene: ssl_div_a.yaml\nprefix: 'a b'\n", "prefix", "letters");
  ExpectError("scene: ssl_div_a.yaml\nrealism: lifelike\n", "realism", "preset");
  ExpectError("scene: simspark_match.yaml\nrealism: lifelike\n", "realism", "preset");  // legged: encoders, IMU
  ExpectError("scene: ssl_div_a.yaml\nbridges: {simspark: {}}\n", "bridges.simspark", "works with legged");
  ExpectError("scene: simspark_match.yaml\nbridges: {grsim: {}}\n", "bridges.grsim", "works with SSL");
  ExpectError("scene: ssl_div_a.yaml\nbridges: {grsm: {}}\n", "bridges.grsm", "unknown key");
  ExpectError("scene: ssl_div_a.yaml\nbridges: {sim: {}}\n", "bridges.sim", "unknown key");
  ExpectError("scene: ssl_div_a.yaml\nbridges: {grsim: {domain: 3}}\n", "bridges.grsim.domain", "top-level");
  ExpectError("scene: ssl_div_a.yaml\nsim: {scene: x.yaml}\n", "sim.scene", "top-level");
  ExpectError("scene: ssl_div_a.yaml\nsim: {Speed: 2}\n", "sim.Speed", "not a flag name");
  ExpectError("scene: ssl_div_a.yaml\nsim: {speed: {x: 1}}\n", "sim.speed", "expected a value");
  ExpectError("scene: ssl_div_a.yaml\nbridges: {vision: 3}\n", "bridges.vision", "expected a map");
  ExpectError("scene: ssl_div_a.yaml\ndiscovery: {server: 10.0.0.1}\n", "discovery.server", "HOST:PORT");
  ExpectError("scene: ssl_div_a.yaml\ndiscovery: {start: true}\n", "discovery.start", "needs discovery.server");
  ExpectError("scene: ssl_div_a.yaml\nrestart: {max_restart: 3}\n", "restart.max_restart", "max_restarts");
  ExpectError("scene: ssl_div_a.yaml\nstop_grace: 0\n", "stop_grace", "> 0");
  // Durations past an hour (1e300 s was a nanosecond count past int64: SIGKILL at once, no backoff).
  ExpectError("scene: ssl_div_a.yaml\nstop_grace: 1e300\n", "stop_grace", "<= 3600");
  ExpectError("scene: ssl_div_a.yaml\nrestart: {backoff_max: 1e300}\n", "restart.backoff_max", "<= 3600");
  ExpectError("scene: ssl_div_a.yaml\nbrigdes: {}\n", "brigdes", "did you mean bridges");
}

TEST(LaunchProfile, HostPort) {
  std::string host;
  int port = 0;
  EXPECT_TRUE(ParseHostPort("192.168.1.10:11811", &host, &port));
  EXPECT_EQ(host, "192.168.1.10");
  EXPECT_EQ(port, 11811);
  EXPECT_TRUE(ParseHostPort("discovery:11811", &host, &port));
  for (const char* bad : {"1.2.3:11811", "1.2.3.4", ":11811", "1.2.3.4:0", "1.2.3.4:70000", "a b:1", "h:x"})
    EXPECT_FALSE(ParseHostPort(bad, &host, &port)) << bad;
}

TEST(LaunchPlan, OverridesReachEveryProcess) {
  const ProfileLoadResult r = LoadLaunchProfile("ssl_div_a", DefaultProfileDir());
  ASSERT_TRUE(r.profile.has_value());
  LaunchOverrides o;
  o.domain = 17;
  o.prefix = "match2";
  o.realism = "ideal";
  o.discovery_server = "10.1.2.3:11811";
  o.start_discovery_server = true;
  o.sets = {"vision.port=10006", "sim.speed=max", "vision.tracked=true"};
  const LaunchPlan plan = BuildPlan(*r.profile, o, kLauncherDir);
  ASSERT_TRUE(plan.errors.empty()) << plan.errors[0];
  ASSERT_EQ(plan.commands.size(), 6u);
  EXPECT_EQ(plan.commands[0].name, "discovery");
  EXPECT_EQ(Args(plan.commands[0]), "-i 0 -l 10.1.2.3 -p 11811 ");
  EXPECT_TRUE(plan.commands[0].stop_last) << "the discovery server goes last";
  EXPECT_TRUE(plan.commands[0].env.empty());
  for (size_t i = 1; i < plan.commands.size(); ++i) {
    const ProcessCommand& c = plan.commands[i];
    EXPECT_NE(Args(c).find("--domain 17 --prefix match2 "), std::string::npos) << Args(c);
    ASSERT_EQ(c.env.size(), 1u);
    EXPECT_EQ(c.env[0].first, "ROS_DISCOVERY_SERVER");
    EXPECT_EQ(c.env[0].second, "10.1.2.3:11811");
  }
  EXPECT_NE(Args(plan.commands[1]).find("--realism ideal"), std::string::npos);
  EXPECT_NE(Args(plan.commands[1]).find("--speed max"), std::string::npos);
  EXPECT_NE(Args(plan.commands[3]).find("--port 10006 --tracked"), std::string::npos) << Args(plan.commands[3]);
}

TEST(LaunchPlan, OnlyAndBadOverrides) {
  const ProfileLoadResult r = LoadLaunchProfile("ssl_div_b", DefaultProfileDir());
  ASSERT_TRUE(r.profile.has_value());
  LaunchOverrides o;
  o.only = {"vision", "grsim"};
  LaunchPlan plan = BuildPlan(*r.profile, o, kLauncherDir);
  ASSERT_TRUE(plan.errors.empty()) << plan.errors[0];
  ASSERT_EQ(plan.commands.size(), 2u);
  EXPECT_EQ(plan.commands[0].name, "grsim");  // profile order, not --only order
  EXPECT_TRUE(plan.commands[0].env.empty());

  LaunchOverrides bad;
  bad.only = {"tracker"};
  bad.sets = {"vision.domain=3", "vision", "tracker.port=1"};
  bad.domain = 999;
  bad.start_discovery_server = true;
  plan = BuildPlan(*r.profile, bad, kLauncherDir);
  EXPECT_EQ(plan.errors.size(), 6u);
}

// --security DIR: each process runs as its identity (programs.h), the viewer as the operator; not with a
// discovery server (it would be an unauthenticated participant).
TEST(LaunchPlan, SecurityGivesEachProcessItsIdentity) {
  const ProfileLoadResult r = LoadLaunchProfile("ssl_div_a", DefaultProfileDir());
  ASSERT_TRUE(r.profile.has_value());
  LaunchOverrides o;
  o.security = "/sec";
  LaunchPlan plan = BuildPlan(*r.profile, o, kLauncherDir);
  ASSERT_TRUE(plan.errors.empty()) << plan.errors[0];
  std::map<std::string, std::string> expected = {{"sim", "sim"},
                                                 {"grsim", "grsim-bridge"},
                                                 {"vision", "vision-bridge"},
                                                 {"simproto", "simproto-bridge"},
                                                 {"viewer", "operator"}};
  ASSERT_EQ(plan.commands.size(), expected.size());
  for (const ProcessCommand& c : plan.commands)
    EXPECT_NE(Args(c).find("--security /sec/" + expected.at(c.name) + " "), std::string::npos) << Args(c);

  o.discovery_server = "10.1.2.3:11811";
  plan = BuildPlan(*r.profile, o, kLauncherDir);
  ASSERT_EQ(plan.errors.size(), 1u);
  EXPECT_NE(plan.errors[0].find("--security with a discovery server"), std::string::npos) << plan.errors[0];
}

TEST(LaunchPlan, BinariesAreFoundInTheBuildTree) {
  const ProfileLoadResult r = LoadLaunchProfile("ssl_div_a", DefaultProfileDir());
  ASSERT_TRUE(r.profile.has_value());
  // As `turf` finds them next to itself: <build>/participants/launcher/../<dir>/<binary>.
  const LaunchPlan plan = BuildPlan(*r.profile, {}, kLauncherDir);
  ASSERT_TRUE(plan.errors.empty()) << plan.errors[0];
  for (const ProcessCommand& c : plan.commands) {
    const Program* program = FindProgram(c.name);
    ASSERT_NE(program, nullptr);
    EXPECT_EQ(c.argv[0], std::string(TURF_BINARY_DIR) + "/participants/" + std::string(program->build_dir) + "/" +
                             std::string(program->binary));
  }
  LaunchOverrides o;
  o.bin_dir = "/nonexistent";
  EXPECT_EQ(BuildPlan(*r.profile, o, kLauncherDir).errors.size(), 5u);  // turf-sim, three bridges, the viewer
}

TEST(LaunchPlan, HlvsPlan) {
  const ProfileLoadResult r = LoadLaunchProfile("hlvs", DefaultProfileDir());
  ASSERT_TRUE(r.profile.has_value()) << r.errors[0];
  const LaunchPlan plan = BuildPlan(*r.profile, {}, kLauncherDir);
  ASSERT_TRUE(plan.errors.empty()) << plan.errors[0];
  ASSERT_EQ(plan.commands.size(), 4u);  // turf-sim, the bridge, turf-render, the viewer
  const std::string build = std::string(TURF_BINARY_DIR) + "/participants/";
  EXPECT_EQ(Args(plan.commands[0]), "--scene " + kScenes + "/hlvs.yaml --domain 0 --prefix turf --lockstep ");
  EXPECT_EQ(plan.commands[1].name, "hlvs");
  EXPECT_EQ(plan.commands[1].argv[0], build + "hlvs_bridge/turf-hlvs-bridge");
  EXPECT_EQ(Args(plan.commands[1]), "--domain 0 --prefix turf --listen 0.0.0.0 --realtime-factor 1 --team-players 4 ");
  // turf-render gets the profile's scene, as turf-sim; --set may not change it.
  EXPECT_EQ(plan.commands[2].name, "render");
  EXPECT_EQ(plan.commands[2].argv[0], build + "render/turf-render");
  EXPECT_EQ(Args(plan.commands[2]), "--scene " + kScenes + "/hlvs.yaml --domain 0 --prefix turf --status-every 10 ");
  LaunchOverrides o;
  o.sets = {"render.scene=x.yaml"};
  EXPECT_FALSE(BuildPlan(*r.profile, o, kLauncherDir).errors.empty());
}

TEST(LaunchPlan, SimSparkPlanAndSyncMode) {
  const ProfileLoadResult r = LoadLaunchProfile("simspark", DefaultProfileDir());
  ASSERT_TRUE(r.profile.has_value()) << r.errors[0];
  LaunchPlan plan = BuildPlan(*r.profile, {}, kLauncherDir);
  ASSERT_TRUE(plan.errors.empty()) << plan.errors[0];
  ASSERT_EQ(plan.commands.size(), 3u);  // turf-sim, the bridge, the viewer
  const std::string build = std::string(TURF_BINARY_DIR) + "/participants/";
  EXPECT_EQ(plan.commands[0].name, "sim");
  EXPECT_EQ(plan.commands[0].argv[0], build + "sim/turf-sim");
  EXPECT_EQ(Args(plan.commands[0]), "--scene " + kScenes + "/simspark_match.yaml --domain 0 --prefix turf --lockstep ");
  EXPECT_EQ(plan.commands[1].name, "simspark");
  EXPECT_EQ(plan.commands[1].argv[0], build + "simspark_bridge/turf-simspark-bridge");
  EXPECT_EQ(Args(plan.commands[1]), "--domain 0 --prefix turf --listen 0.0.0.0 --agent-port 3100 --monitor-port 3200 ");

  // Sync mode and other ports, as the profile's comment says.
  LaunchOverrides o;
  o.domain = 7;
  o.sets = {"simspark.sync=true", "simspark.agent-port=3110", "simspark.monitor-port=3210"};
  plan = BuildPlan(*r.profile, o, kLauncherDir);
  ASSERT_TRUE(plan.errors.empty()) << plan.errors[0];
  ASSERT_EQ(plan.commands.size(), 3u);
  EXPECT_EQ(Args(plan.commands[1]),
            "--domain 7 --prefix turf --listen 0.0.0.0 --sync --agent-port 3110 "
            "--monitor-port 3210 ");
  o.sets = {"simspark.sync=false"};
  EXPECT_EQ(Args(BuildPlan(*r.profile, o, kLauncherDir).commands[1]).find("--sync"), std::string::npos);

  // One process per host.
  for (const char* only : {"sim", "simspark"}) {
    LaunchOverrides one;
    one.only = {only};
    plan = BuildPlan(*r.profile, one, kLauncherDir);
    ASSERT_TRUE(plan.errors.empty()) << plan.errors[0];
    ASSERT_EQ(plan.commands.size(), 1u);
    EXPECT_EQ(plan.commands[0].name, only);
  }

  // SSL-only overrides are refused by name; realism applies (encoders, IMU).
  LaunchOverrides bad;
  bad.realism = "ideal";
  bad.only = {"grsim"};
  bad.sets = {"vision.port=10006"};
  plan = BuildPlan(*r.profile, bad, kLauncherDir);
  ASSERT_EQ(plan.errors.size(), 2u);
  for (const std::string& e : plan.errors) EXPECT_EQ(e.find("realism"), std::string::npos) << e;
}

TEST(LaunchPlan, ShellLineQuotes) {
  const ProcessCommand c{"sim", {"/opt/turf bin/turf-sim", "--prefix", "it's", "--speed", "1"}, {{"A", "x y"}}};
  EXPECT_EQ(ShellLine(c), "A='x y' '/opt/turf bin/turf-sim' --prefix 'it'\\''s' --speed 1");
}

// What the launcher prints first: where the page is and where team software points, from the plan's flags.
TEST(LaunchPlan, WhereToLookNamesTheViewerAndThePorts) {
  const ProfileLoadResult r = LoadLaunchProfile("ssl_div_a", DefaultProfileDir());
  ASSERT_TRUE(r.profile.has_value());
  LaunchOverrides o;
  o.sets = {"viewer.port=8181", "grsim.port=20111"};
  const std::vector<std::string> lines = WhereToLook(BuildPlan(*r.profile, o, kLauncherDir));
  ASSERT_EQ(lines.size(), 4u);
  EXPECT_EQ(lines[0].rfind("grSim commands and replacement: UDP 0.0.0.0:20111 ", 0), 0u) << lines[0];
  EXPECT_EQ(lines[1], "SSL-Vision: UDP 224.5.23.2:10020");
  EXPECT_EQ(lines[2], "SSL simulation protocol: UDP 0.0.0.0: control 10300, blue 10301, yellow 10302; sync off");
  EXPECT_EQ(lines[3], "viewer: http://127.0.0.1:8181/");
  // The sync port binds 127.0.0.1 unless told otherwise; a front-end in turf-sim has its line too.
  LaunchOverrides sync;
  sync.sets = {"simproto.sync=true"};
  EXPECT_EQ(WhereToLook(BuildPlan(*r.profile, sync, kLauncherDir))[2],
            "SSL simulation protocol: UDP 0.0.0.0: control 10300, blue 10301, yellow 10302; sync 127.0.0.1:10303");
  LaunchOverrides in_sim;
  in_sim.only = {"sim"};
  in_sim.sets = {"sim.simproto=0.0.0.0", "sim.simproto-control-port=10400"};
  EXPECT_EQ(WhereToLook(BuildPlan(*r.profile, in_sim, kLauncherDir)),
            std::vector<std::string>{"SSL simulation protocol (in turf-sim): UDP 0.0.0.0: control 10400, blue 10301, "
                                     "yellow 10302; sync off"});
  const ProfileLoadResult b = LoadLaunchProfile("booster", DefaultProfileDir());
  ASSERT_TRUE(b.profile.has_value());
  const std::vector<std::string> booster = WhereToLook(BuildPlan(*b.profile, {}, kLauncherDir));
  ASSERT_FALSE(booster.empty());
  EXPECT_EQ(booster[0],
            "Booster SDK (in turf-sim): the first robot's topics on DDS domain 0, the next robot's on the next domain");
  const ProfileLoadResult s = LoadLaunchProfile("simspark", DefaultProfileDir());
  ASSERT_TRUE(s.profile.has_value());
  LaunchOverrides only_sim;
  only_sim.only = {"sim"};
  EXPECT_TRUE(WhereToLook(BuildPlan(*s.profile, only_sim, kLauncherDir)).empty()) << "nothing served here";
  const std::vector<std::string> all = WhereToLook(BuildPlan(*s.profile, {}, kLauncherDir));
  ASSERT_EQ(all.size(), 2u);
  EXPECT_EQ(all[0], "SimSpark: TCP 0.0.0.0: agents 3100, monitors and trainers 3200");
}

// RCSSServerMJ: served by turf-sim itself (--rcssservermj), no bridge process; sync mode and other ports by --set.
TEST(LaunchPlan, RcssServerMjPlanServedInTurfSim) {
  const ProfileLoadResult r = LoadLaunchProfile("rcssservermj", DefaultProfileDir());
  ASSERT_TRUE(r.profile.has_value()) << r.errors[0];
  LaunchOverrides o;
  o.sets = {"sim.rcssservermj-sync=true", "sim.rcssservermj-agent-port=60100"};
  const LaunchPlan plan = BuildPlan(*r.profile, o, kLauncherDir);
  ASSERT_TRUE(plan.errors.empty()) << plan.errors[0];
  ASSERT_EQ(plan.commands.size(), 2u);  // turf-sim, the viewer
  EXPECT_EQ(plan.commands[0].name, "sim");
  const std::string args = Args(plan.commands[0]);
  EXPECT_EQ(args.rfind("--scene " + kScenes + "/rcssservermj_fifa.yaml --domain 0 --prefix turf ", 0), 0u) << args;
  EXPECT_NE(args.find("--rcssservermj 127.0.0.1 "), std::string::npos) << args;
  EXPECT_NE(args.find("--rcssservermj-agent-port 60100 "), std::string::npos) << args;
  EXPECT_NE(args.find("--rcssservermj-sync "), std::string::npos) << args;
  const std::vector<std::string> lines = WhereToLook(plan);
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0], "RCSSServerMJ (in turf-sim): TCP 127.0.0.1: agents 60100, monitor commands 60001");
}

// turf launch --scene: another scene of the profile's kind replaces its scene (the 1 v 1 RCSSServerMJ scene); a
// scene of the other kind or a missing file is refused, naming why.
TEST(LaunchProfile, SceneOptionReplacesTheSceneWithOneOfTheSameKind) {
  const ProfileLoadResult r =
      LoadLaunchProfile("rcssservermj", DefaultProfileDir(), kScenes + "/rcssservermj_fifa_1v1.yaml");
  ASSERT_TRUE(r.profile.has_value()) << r.errors[0];
  EXPECT_TRUE(r.profile->legged);
  const LaunchPlan plan = BuildPlan(*r.profile, {}, kLauncherDir);
  ASSERT_TRUE(plan.errors.empty()) << plan.errors[0];
  const std::string args = Args(plan.commands[0]);
  EXPECT_EQ(args.rfind("--scene " + kScenes + "/rcssservermj_fifa_1v1.yaml --domain 0 ", 0), 0u) << args;

  const ProfileLoadResult ssl = LoadLaunchProfile("rcssservermj", DefaultProfileDir(), kScenes + "/ssl_div_a.yaml");
  EXPECT_FALSE(ssl.profile.has_value());
  ASSERT_EQ(ssl.errors.size(), 1u);
  EXPECT_NE(ssl.errors[0].find("ssl_div_a.yaml is an SSL scene; this profile runs a legged scene"), std::string::npos)
      << ssl.errors[0];
  const ProfileLoadResult legged = LoadLaunchProfile("ssl_div_a", DefaultProfileDir(), kScenes + "/simspark_3d.yaml");
  ASSERT_EQ(legged.errors.size(), 1u);
  EXPECT_NE(legged.errors[0].find("is a legged scene; this profile runs an SSL scene"), std::string::npos)
      << legged.errors[0];
  const ProfileLoadResult missing = LoadLaunchProfile("rcssservermj", DefaultProfileDir(), kScenes + "/none.yaml");
  ASSERT_EQ(missing.errors.size(), 1u);
  EXPECT_NE(missing.errors[0].find("--scene: no such file"), std::string::npos) << missing.errors[0];
}

}  // namespace
}  // namespace turf::launch
