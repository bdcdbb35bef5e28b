// turf-bench-sim: how fast turf-sim runs a scene free-running, with world
// state and camera detections published over DDS. With --subscribe a child
// process (like a team stack) receives them; with --drive it also commands
// every robot at each world state. Prints one table row; bench/run.sh runs the
// standard set, one process each so peak memory is per configuration.
#include <spdlog/spdlog.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <turf/idl/SslRobotPubSubTypes.h>
#include <turf/idl/SslVisionPubSubTypes.h>
#include <turf/idl/WorldStatePubSubTypes.h>
#include <unistd.h>
#include <CLI/CLI.hpp>

#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <thread>

#include "dds/participant.h"
#include "loader/scene_yaml.h"
#include "participants/common/process.h"
#include "participants/sim/sim_node.h"

namespace {

struct Received {
  uint64_t states = 0;
  uint64_t frames = 0;
};

// The child: subscribes (and drives) until SIGTERM, then reports what it got.
Received RunClient(const turf::dds::ParticipantOptions& o, bool drive) {
  namespace idl = turf::idl;
  using turf::dds::Topic;
  turf::dds::Participant client(o);
  auto states = client.MakeReader<idl::WorldStatePubSubType>(Topic::kWorldState);
  auto frames = client.MakeReader<idl::CameraFramePubSubType>(Topic::kSslCamera);
  auto blue = client.MakeWriter<idl::SslRobotCommandPubSubType>(Topic::kSslCommandBlue);
  auto yellow = client.MakeWriter<idl::SslRobotCommandPubSubType>(Topic::kSslCommandYellow);
  Received got;
  std::vector<idl::WorldState> s;
  std::vector<idl::CameraFrame> f;
  while (!turf::StopRequested()) {
    if (frames->Take(&f)) got.frames += f.size();
    if (!states->Take(&s)) {
      std::this_thread::sleep_for(std::chrono::microseconds(500));
      continue;
    }
    got.states += s.size();
    if (!drive) continue;
    // Everyone drives a slow figure-eight: turning, crossing, bumping.
    const double t = s.back().sim_time_ns() * 1e-9;
    for (const auto& r : s.back().robots()) {
      if (!r.on_field()) continue;
      idl::SslRobotCommand c;
      c.team(r.team());
      c.id(r.id());
      c.move(idl::MOVE_LOCAL_VELOCITY);
      c.velocity().x(1.5 * std::sin(0.5 * t + r.id()));
      c.velocity().y(1.0 * std::cos(0.7 * t + 2 * r.id()));
      c.velocity().z(2.0 * std::sin(0.3 * t));
      (r.team() == idl::TEAM_BLUE ? blue : yellow)->Write(c);
    }
  }
  return got;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"turf-bench-sim: real-time factor of turf-sim, free-running, publishing on DDS"};
  std::string scene_path;
  double seconds = 20.0;
  bool subscribe = false;
  bool drive = false;
  bool header = false;
  std::string security;
  app.add_option("--scene", scene_path, "scene file")->required();
  app.add_option("--seconds", seconds, "simulated seconds to run")->capture_default_str();
  app.add_flag("--subscribe", subscribe, "a second process subscribes to world state and cameras");
  app.add_flag("--drive", drive, "the second process also commands every robot at each world state");
  app.add_flag("--header", header, "print the table header first");
  app.add_option("--security", security,
                 "DDS Security: a `turf security init --prefix '*'` directory; turf-sim runs as its sim identity, "
                 "the client as simproto-bridge (which may command both teams)");
  CLI11_PARSE(app, argc, argv);
  subscribe = subscribe || drive;
  spdlog::set_level(spdlog::level::warn);

  auto loaded = turf::LoadSceneFile(scene_path);
  if (!loaded.scene) {
    for (const auto& e : loaded.errors) std::fprintf(stderr, "%s\n", e.c_str());
    return 2;
  }
  int on_field = 0;
  for (const auto& r : loaded.scene->robots) on_field += r.on_field;
  // Domains <= 99 keep Fast DDS ports out of the ephemeral range (tests/test_domain.h).
  turf::dds::ParticipantOptions dds{1 + static_cast<int>(getpid() % 99), "bench", "bench" + std::to_string(getpid()),
                                    ""};

  int pipe_fd[2] = {-1, -1};
  pid_t child = -1;
  if (subscribe) {
    if (pipe(pipe_fd) != 0) return 1;
    child = fork();
    if (child == 0) {
      close(pipe_fd[0]);
      turf::InstallStopSignals();
      dds.name = "bench-client";
      if (!security.empty()) dds.security = security + "/simproto-bridge";
      const Received got = RunClient(dds, drive);
      const ssize_t n = write(pipe_fd[1], &got, sizeof(got));
      _exit(n == sizeof(got) ? 0 : 1);
    }
    close(pipe_fd[1]);
  }

  turf::SimNodeOptions options;
  options.domain = dds.domain;
  options.prefix = dds.prefix;
  options.mode = turf::TimeMode::kFreeRunning;
  options.duration = seconds;
  if (!security.empty()) options.security = security + "/sim";
  turf::SimNode node(std::move(*loaded.scene), options);
  if (subscribe) std::this_thread::sleep_for(std::chrono::seconds(2));  // discovery
  const auto t0 = std::chrono::steady_clock::now();
  node.Run([] { return false; });
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  Received got;
  if (subscribe) {
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    kill(child, SIGTERM);
    if (read(pipe_fd[0], &got, sizeof(got)) != sizeof(got)) got = {};
    waitpid(child, nullptr, 0);
  }
  struct rusage usage {};
  getrusage(RUSAGE_SELF, &usage);
  const double cpu =
      usage.ru_utime.tv_sec + usage.ru_utime.tv_usec * 1e-6 + usage.ru_stime.tv_sec + usage.ru_stime.tv_usec * 1e-6;
  const auto stats = node.Stats();
  if (header) {
    std::printf("| %-34s | %6s | %-22s | %6s | %7s | %6s | %8s | %9s |\n", "scene", "robots", "client process", "sim s",
                "wall s", "RTF", "sim CPU", "peak MiB");
    std::printf("|%s|%s|%s|%s|%s|%s|%s|%s|\n", std::string(36, '-').c_str(), std::string(8, '-').c_str(),
                std::string(24, '-').c_str(), std::string(8, '-').c_str(), std::string(9, '-').c_str(),
                std::string(8, '-').c_str(), std::string(10, '-').c_str(), std::string(11, '-').c_str());
  }
  std::string name = scene_path.substr(scene_path.find_last_of('/') + 1);
  if (!security.empty()) name += ", " + security.substr(security.find_last_of('/') + 1);
  const std::string client =
      !subscribe ? "none" : fmt::format("{} {}/{}", drive ? "drive" : "listen", got.states, got.frames);
  std::printf("| %-34s | %6d | %-22s | %6.1f | %7.2f | %5.1fx | %7.2fs | %9.1f |\n", name.c_str(), on_field,
              client.c_str(), stats.sim_time_ns * 1e-9, wall, stats.sim_time_ns * 1e-9 / wall, cpu,
              usage.ru_maxrss / 1024.0);
  return 0;
}
