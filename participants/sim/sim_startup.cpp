#include "participants/sim/sim_startup.h"

#include <mujoco/mujoco.h>
#include <spdlog/spdlog.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "dds/participant.h"
#include "kernel/time_control.h"
#include "loader/legged_scene_yaml.h"
#include "loader/realism_yaml.h"
#include "loader/scene_yaml.h"
#include "loader/text_file.h"
#include "participants/common/cli_checks.h"
#include "participants/common/process.h"
#include "participants/common/writer_watch.h"
#include "participants/rcssservermj_bridge/rcssservermj_flags.h"
#include "participants/sim/sim_host.h"
#include "participants/sim/sim_node.h"
#include "participants/simproto_bridge/simproto_flags.h"
#include "participants/simspark_bridge/simspark_flags.h"

namespace turf {
namespace {

void MujocoWarning(const char* message) { spdlog::warn("MuJoCo: {}", message); }
// MuJoCo's fatal errors (a model it cannot allocate): its own handler exits, or waits for Enter when stdin is open.
// Named, then the exit code of a configuration turf-sim cannot run.
[[noreturn]] void MujocoError(const char* message) {
  spdlog::critical("MuJoCo: {} (the scene or a robot model asks for what MuJoCo cannot make)", message);
  spdlog::default_logger()->flush();
  std::_Exit(kExitBadConfig);
}

// The realism preset or file named on the command line.
std::optional<SensorRealism> LoadRealismOption(const std::string& realism) {
  const RealismLoadResult r = LoadRealism(realism);
  if (!r.realism) {
    spdlog::error("cannot load realism '{}':", realism);
    for (const std::string& e : r.errors) spdlog::error("  {}", e);
    return std::nullopt;
  }
  spdlog::info("sensor realism from '{}'", realism);
  return r.realism;
}

// How long turf-sim waits, once its writers exist, for discovery to show another simulator on its domain and prefix.
// Discovery on one host or a LAN takes tens of milliseconds (a new participant announces itself every 0.1 s at
// first); the window leaves room for a loaded host or a lossy network. Start-up takes the whole window when there is
// no other simulator: nothing in discovery says "that was everyone".
constexpr std::chrono::milliseconds kDiscoveryWindow{1500};

// Runs the node (`run`) unless another simulator already writes the world state on this domain and prefix (issue
// 20): then exits 2 with one line naming it. While running, another writer that appears is reported as an error
// (WriterWatch) and the node keeps publishing: stopping would leave the other one, which may be the wrong world,
// alone; an operator decides which one goes.
int RunAlone(dds::Participant& dds, const std::function<void()>& run) {
  const auto start = std::chrono::steady_clock::now();
  if (const std::optional<dds::RemoteWriter> other =
          FindEarlierWriter(dds, dds::Topic::kWorldState, kDiscoveryWindow)) {
    spdlog::error("{}", RefusalLine(dds, dds::Topic::kWorldState, *other));
    return kExitBadConfig;
  }
  if (StopRequested()) return kExitClean;  // asked to stop while starting: nothing to run
  spdlog::debug(
      "no other simulator on {} after {} ms of discovery", dds.TopicName(dds::Topic::kWorldState),
      std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::steady_clock::now() - start).count());
  WriterWatch watch(dds, {{dds::Topic::kWorldState}, /*own_writer=*/true});
  run();
  if (const uint64_t n = watch.Conflicts(); n > 0)
    spdlog::warn("{} other writer(s) of {} appeared while this simulator ran", n,
                 dds.TopicName(dds::Topic::kWorldState));
  return kExitClean;
}

// Either kind of scene: the command line's realism, then turf-sim's node alone or with the front-end the command
// line asks for in this process (sim_host.h); the other kind's front-end is refused.
// What sim/run publishes: the scene file's text and directory, the realism flag and the seed, so a recording can
// be re-simulated from the file alone (turf replay --resimulate).
SceneSource SourceOf(const SimCommandLine& command_line, bool legged, const std::string& name, uint64_t seed) {
  SceneSource s{legged ? "legged" : "ssl", name, command_line.scene_path, "", "", command_line.realism, seed};
  std::error_code ec;
  s.dir = std::filesystem::absolute(command_line.scene_path, ec).parent_path().string();
  std::string error;
  if (!ReadTextFile(command_line.scene_path, 1u << 20, &s.yaml, &error))
    spdlog::warn("sim/run: cannot read {} again ({}): a recording of this run cannot be re-simulated",
                 command_line.scene_path, error);
  return s;
}

template <class SceneKind>
int RunScene(SceneKind scene, const SimCommandLine& command_line, bool legged) {
  SimNodeOptions options = command_line.node;
  options.scene_source = SourceOf(command_line, legged, scene.name, scene.seed);
  if (!command_line.realism.empty()) {
    const std::optional<SensorRealism> r = LoadRealismOption(command_line.realism);
    if (!r) return kExitBadConfig;
    scene.realism = *r;  // legged scenes: the encoders, IMU and touch streams
  }
  if (legged ? command_line.simproto : (command_line.simspark || command_line.rcssservermj || command_line.booster)) {
    spdlog::error(legged ? "--simproto serves the SSL simulation protocol: it needs an SSL scene, not a legged one"
                         : "--simspark, --rcssservermj and --booster-sdk serve legged robots: they need a legged scene "
                           "(kind: legged), not an SSL one");
    return kExitBadConfig;
  }
  if (legged && command_line.simspark && command_line.rcssservermj) {
    spdlog::error("--simspark and --rcssservermj both drive the match's clock: choose one");
    return kExitBadConfig;
  }
  if (legged && (command_line.simspark || command_line.rcssservermj) && options.mode != TimeMode::kLockstep) {
    // The front-end is the match's clock: from the first frame, so the world does not run on in real time until it
    // has attached (it began 0 or 1 cycles later, by timing: the same agents' stream gave other perceptions).
    options.mode = TimeMode::kLockstep;
    spdlog::info("time: lockstep from the start (the {} front-end in this process is the clock)",
                 command_line.simspark ? "SimSpark" : "RCSSServerMJ");
  }
  if (legged ? (command_line.simspark || command_line.rcssservermj || command_line.booster) : command_line.simproto) {
    InProcessFrontEnds front_ends;
    if (legged && command_line.simspark) front_ends.simspark = command_line.simspark_options;
    if (legged && command_line.rcssservermj) front_ends.rcssservermj = command_line.rcssservermj_options;
    if (legged && command_line.booster) {
      front_ends.booster = command_line.booster_options;
      front_ends.booster->turf_domain = options.domain;
    }
    if (!legged) front_ends.simproto = command_line.simproto_options;
    SimHost host(std::move(scene), options, std::move(front_ends));
    return RunAlone(host.participant(), [&] { host.Run(StopRequested); });
  }
  dds::Participant dds(DdsOptions(options));  // outlives the node
  SimNode node(std::move(scene), options, dds);
  return RunAlone(dds, [&] { node.Run(StopRequested); });
}

// A scene file read by `load` (its errors named), then run.
template <class Loaded>
int RunLoaded(Loaded loaded, const SimCommandLine& command_line, const char* what, bool legged) {
  if (!loaded.scene) {
    spdlog::error("cannot load {} {}:", what, command_line.scene_path);
    for (const std::string& e : loaded.errors) spdlog::error("  {}", e);
    return kExitBadConfig;
  }
  spdlog::info("{} file {}", what, command_line.scene_path);
  return RunScene(std::move(*loaded.scene), command_line, legged);
}

// Scenes with `kind: legged`: any MJCF robots on joint topics (sim_node.h).
int RunLegged(const SimCommandLine& command_line) {
  return RunLoaded(LoadLeggedSceneFile(command_line.scene_path), command_line, "legged scene", /*legged=*/true);
}

int RunSsl(const SimCommandLine& command_line) {
  return RunLoaded(LoadSceneFile(command_line.scene_path), command_line, "scene", /*legged=*/false);
}

// A front-end served in this process, `--NAME [ADDRESS]`: whether it was given, and the address it binds.
struct ServedHere {
  CLI::Option* option;
  bool* given;
  std::string* listen;
};

// Adds `--NAME [ADDRESS]`; given without an address (CLI11 then leaves it empty), it binds 127.0.0.1.
ServedHere AddServedHere(CLI::App& app, const std::string& flag, const std::string& help, std::string* listen,
                         bool* given) {
  *listen = "127.0.0.1";
  return {app.add_option(flag, *listen, help)->expected(0, 1)->type_name("[ADDRESS]"), given, listen};
}

}  // namespace

void AddSimFlags(ParticipantMain& participant, SimCommandLine& command_line) {
  CLI::App& app = participant.app();
  std::vector<ServedHere> served;
  SimNodeOptions& node = command_line.node;
  command_line.scene_path = std::string(TURF_SOURCE_DIR) + "/configs/scenes/ssl_div_a.yaml";
  app.add_option("-s,--scene", command_line.scene_path, "scene file (YAML)")->capture_default_str();
  participant.AddCommonFlags(node, {"DDS domain id", "topic name prefix (two matches on one network: use two)"});
  app.add_option("--speed", command_line.speed, "multiple of real time, or 'max' to run free")->capture_default_str();
  app.add_flag("--lockstep", command_line.lockstep, "advance only on STEP control requests");
  app.add_flag("--paused", node.start_paused, "start paused");
  app.add_option("--realism", command_line.realism,
                 "sensor realism: a preset (ideal, realistic, harsh in configs/realism/) or a YAML file; "
                 "overrides the scene's");
  app.add_option("--duration", node.duration, "stop after this many simulated seconds (0: run until Ctrl-C)")
      ->check(FiniteAtLeastZero());
  app.add_option("--resume-dir", node.resume_dir,
                 "write a snapshot of the match to DIR/<prefix>.resume every --snapshot-every s of sim time, and "
                 "continue from it when started again (after a crash; `turf launch` passes a directory of its own)")
      ->check(CLI::ExistingDirectory);
  app.add_option("--snapshot-every", node.snapshot_every, "with --resume-dir: seconds of sim time between snapshots")
      ->check(CLI::Range(0.01, 3600.0))
      ->capture_default_str();

  // The SSL simulation protocol in this process (sim_host.h): the same ports as turf-simproto-bridge.
  SimprotoBridgeOptions& sp = command_line.simproto_options;
  sp.name = "turf-sim/simproto";
  served.push_back(
      AddServedHere(app, "--simproto",
                    "serve the SSL simulation protocol (UDP: control, blue, yellow and sync ports) in this "
                    "process, with no DDS hop to the physics; binds ADDRESS (default 127.0.0.1; 0.0.0.0: "
                    "every interface). turf-simproto-bridge still works as a separate process",
                    &sp.listen, &command_line.simproto));
  AddSimprotoPortFlags(app, sp, "simproto-", "with --simproto: ");
  AddSimprotoAllowFlags(app, sp, "simproto-", "with --simproto: ");

  // SimSpark agents and monitors in this process (sim_host.h): the same ports as turf-simspark-bridge.
  SimSparkBridgeOptions& ss = command_line.simspark_options;
  ss.name = "turf-sim/simspark";
  served.push_back(AddServedHere(app, "--simspark",
                                 "legged scenes: serve SimSpark agents and monitors (TCP) in this process, with no "
                                 "DDS hop to the physics; binds ADDRESS (default 127.0.0.1). turf-simspark-bridge "
                                 "still works as a separate process",
                                 &ss.listen, &command_line.simspark));
  AddSimSparkFrontEndFlags(app, ss, "simspark-", "with --simspark: ");

  // RCSSServerMJ agents and monitor commands in this process (sim_host.h): the same flags as
  // turf-rcssservermj-bridge's, prefixed.
  RcssServerMjOptions& mj = command_line.rcssservermj_options;
  mj.name = "turf-sim/rcssservermj";
  served.push_back(AddServedHere(app, "--rcssservermj",
                                 "legged scenes of T1/K1 robots: serve RCSSServerMJ (2026 3D league) agents and "
                                 "monitor commands (TCP) in this process; binds ADDRESS (default 127.0.0.1). "
                                 "turf-rcssservermj-bridge still works as a separate process",
                                 &mj.listen, &command_line.rcssservermj));
  AddRcssServerMjFlags(app, mj, "rcssservermj-", "with --rcssservermj: ");

  // The Booster SDK's DDS topics in this process (participants/booster_bridge/booster_sdk_bridge.h).
  BoosterSdkOptions& bo = command_line.booster_options;
  CLI::Option* booster = app.add_option("--booster-sdk", bo.domain,
                                        "legged scenes: serve the Booster SDK's low-level DDS topics (rt/low_state, "
                                        "rt/joint_ctrl, rt/odometer_state, rt/fall_down) for every T1 and K1, the "
                                        "first robot on DDS domain DOMAIN (default 0, as the SDK's examples), the "
                                        "next on DOMAIN+1, ...")
                             ->expected(0, 1)
                             ->type_name("[DOMAIN]")
                             ->check(CLI::Range(0, 232));
  app.add_option("--booster-command-timeout", bo.command_timeout,
                 "with --booster-sdk: a joint_ctrl sample older than this (ms, by its source timestamp) is refused")
      ->capture_default_str();

  app.parse_complete_callback([&command_line, served, booster] {
    command_line.booster = booster->count() > 0;
    for (const ServedHere& s : served) {
      *s.given = s.option->count() > 0;
      if (s.listen->empty()) *s.listen = "127.0.0.1";
    }
  });
}

bool ApplyTimeMode(const std::string& speed, bool lockstep, SimNodeOptions& node) {
  if (lockstep) {
    node.mode = TimeMode::kLockstep;
    return true;
  }
  if (speed == "max") {
    node.mode = TimeMode::kFreeRunning;
    return true;
  }
  try {
    node.speed = std::stod(speed);
  } catch (const std::exception&) {
    node.speed = NAN;
  }
  if (!(std::isfinite(node.speed) && node.speed >= kMinTimeSpeed && node.speed <= kMaxTimeSpeed)) {
    spdlog::error("--speed must be a number in [{}, {}] or 'max' (got '{}')", kMinTimeSpeed, kMaxTimeSpeed, speed);
    return false;
  }
  node.mode = node.speed == 1.0 ? TimeMode::kRealtime : TimeMode::kScaled;
  return true;
}

int RunSim(SimCommandLine command_line) {
  if (!ApplyTimeMode(command_line.speed, command_line.lockstep, command_line.node)) return kExitBadConfig;
  mju_user_warning = MujocoWarning;
  mju_user_error = MujocoError;
  return IsLeggedSceneFile(command_line.scene_path) ? RunLegged(command_line) : RunSsl(command_line);
}

}  // namespace turf
