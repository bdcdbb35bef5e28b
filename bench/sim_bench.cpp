// turf-bench-sim: how fast turf-sim runs a scene free-running, with world
// state and camera detections published over DDS (optionally to a subscriber
// in another thread of this process). Prints one table row; bench/run.sh runs
// the standard set, one process each so peak memory is per configuration.
#include <CLI/CLI.hpp>
#include <spdlog/spdlog.h>
#include <sys/resource.h>
#include <turf/idl/SslVisionPubSubTypes.h>
#include <turf/idl/WorldStatePubSubTypes.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <thread>

#include "config/scene_yaml.h"
#include "dds/participant.h"
#include "participants/sim/sim_node.h"

int main(int argc, char** argv) {
  CLI::App app{"turf-bench-sim: real-time factor of turf-sim, free-running, publishing on DDS"};
  std::string scene_path;
  double seconds = 20.0;
  bool subscribe = false;
  bool header = false;
  app.add_option("--scene", scene_path, "scene file")->required();
  app.add_option("--seconds", seconds, "simulated seconds to run")->capture_default_str();
  app.add_flag("--subscribe", subscribe, "also subscribe to world state and cameras (counts samples)");
  app.add_flag("--header", header, "print the table header first");
  CLI11_PARSE(app, argc, argv);
  spdlog::set_level(spdlog::level::warn);

  auto loaded = turf::LoadSceneFile(scene_path);
  if (!loaded.scene) {
    for (const auto& e : loaded.errors) std::fprintf(stderr, "%s\n", e.c_str());
    return 2;
  }
  int on_field = 0;
  for (const auto& r : loaded.scene->robots) on_field += r.on_field;
  turf::SimNodeOptions options;
  options.domain = 200 + static_cast<int>(getpid() % 30);
  options.prefix = "bench" + std::to_string(getpid());
  options.mode = turf::TimeMode::kFreeRunning;
  options.duration = seconds;

  std::atomic<uint64_t> states{0}, frames{0};
  std::unique_ptr<turf::dds::Participant> client;
  std::unique_ptr<turf::dds::Reader<turf::idl::WorldStatePubSubType>> state_reader;
  std::unique_ptr<turf::dds::Reader<turf::idl::CameraFramePubSubType>> camera_reader;
  turf::SimNode node(std::move(*loaded.scene), options);
  if (subscribe) {
    client = std::make_unique<turf::dds::Participant>(
        turf::dds::ParticipantOptions{options.domain, "bench-client", options.prefix, ""});
    state_reader = client->MakeReader<turf::idl::WorldStatePubSubType>(turf::dds::Topic::kWorldState);
    camera_reader = client->MakeReader<turf::idl::CameraFramePubSubType>(turf::dds::Topic::kSslCamera);
    std::this_thread::sleep_for(std::chrono::seconds(1));  // discovery
  }
  std::atomic<bool> done{false};
  std::thread drain([&] {
    std::vector<turf::idl::WorldState> s;
    std::vector<turf::idl::CameraFrame> f;
    while (!done) {
      if (state_reader && state_reader->Take(&s)) states += s.size();
      if (camera_reader && camera_reader->Take(&f)) frames += f.size();
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
  });
  const auto t0 = std::chrono::steady_clock::now();
  node.Run([] { return false; });
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  done = true;
  drain.join();
  struct rusage usage {};
  getrusage(RUSAGE_SELF, &usage);
  const double cpu = usage.ru_utime.tv_sec + usage.ru_utime.tv_usec * 1e-6 + usage.ru_stime.tv_sec +
                     usage.ru_stime.tv_usec * 1e-6;
  const auto stats = node.Stats();
  if (header) {
    std::printf("| %-22s | %6s | %10s | %8s | %9s | %8s | %10s | %10s |\n", "scene", "robots", "subscriber", "sim s",
                "wall s", "RTF", "CPU s", "peak MiB");
    std::printf("|%s|%s|%s|%s|%s|%s|%s|%s|\n", std::string(24, '-').c_str(), std::string(8, '-').c_str(),
                std::string(12, '-').c_str(), std::string(10, '-').c_str(), std::string(11, '-').c_str(),
                std::string(10, '-').c_str(), std::string(12, '-').c_str(), std::string(12, '-').c_str());
  }
  const std::string name = scene_path.substr(scene_path.find_last_of('/') + 1);
  std::printf("| %-22s | %6d | %10s | %8.1f | %9.2f | %7.1fx | %10.2f | %10.1f |\n", name.c_str(), on_field,
              subscribe ? fmt::format("{}/{}", states.load(), frames.load()).c_str() : "none",
              stats.sim_time_ns * 1e-9, wall, stats.sim_time_ns * 1e-9 / wall, cpu, usage.ru_maxrss / 1024.0);
  return 0;
}
