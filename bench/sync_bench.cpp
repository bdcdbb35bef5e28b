// turf-bench-sync: what the SSL simulation protocol's sync port costs beyond physics, per request.
//
// A UDP client on 127.0.0.1 sends SimulationSyncRequests (sim_step 1/60 s, commands for six robots) one after the
// other and times each from sending it until its SimulationSyncResponse arrives (parsed after), against:
//   (a)  turf-sim's node and a SimprotoBridge on their own DDS participants (what turf-sim plus a separate
//        turf-simproto-bridge process do), both in this process with Fast DDS's intra-process delivery off, so
//        samples take the same transport as between two processes on one host;
//   (b)  turf-sim with the front-end served in its process (SimHost, turf-sim --simproto): the node on DDS and on
//        an in-memory bus, the front-end on the in-memory bus;
//   (b') diagnostic: the node and the front-end on one MemoryBus, no DDS participant at all;
//   (c)  the same number of physics steps of the kernel alone (SslKernel::Step, the same commands), no threads;
//   (u)  the floor for any UDP server of this physics: a thread that runs (c)'s work for each request, then
//        answers with the bytes of a response turf gave (physics plus what the two datagrams and the two thread
//        wake-ups cost on this machine, whoever serves them).
// All run side by side and take one request each in turn, so load from elsewhere falls on every row alike.
// Prints mean, p50 and p99 per request, the overhead beyond physics (each row minus (c)) and beyond the UDP floor
// (each row minus (u)), then the 10th and 25th percentiles and the medians of the per-round differences to (c) and
// (u), which load from elsewhere disturbs less. --cpu N runs every thread on core N (a lockstep client and turf-sim
// never run at once; across cores each request pays two cross-core wake-ups). bench/run.sh sync runs both ways.
#include <sched.h>
#include <spdlog/spdlog.h>
#include <unistd.h>
#include <CLI/CLI.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <numeric>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "bench/bench_qos.h"
#include "codecs/proto/ssl_simulation.pb.h"
#include "codecs/ssl_simulation/step_planner.h"
#include "dds/memory_bus.h"
#include "dds/participant.h"
#include "kernel/ssl_kernel.h"
#include "loader/scene_yaml.h"
#include "participants/common/udp.h"
#include "participants/sim/sim_host.h"
#include "participants/sim/sim_node.h"
#include "participants/simproto_bridge/simproto_bridge.h"

namespace {

using SteadyClock = std::chrono::steady_clock;
using namespace std::chrono_literals;
namespace ws = turf::wire::simulation;

constexpr float kSimStep = 1.0f / 60.0f;
constexpr int kCommanded = 3;  // robots a team

struct Result {
  std::vector<double> us;  // per request
  double Mean() const { return us.empty() ? 0 : std::accumulate(us.begin(), us.end(), 0.0) / us.size(); }
  double Percentile(double p) const {
    if (us.empty()) return 0;
    std::vector<double> v = us;
    std::sort(v.begin(), v.end());
    return v[std::min(v.size() - 1, static_cast<size_t>(p * v.size()))];
  }
  // The median over rounds of (this row's request - `other`'s in the same round): the rows of a round run back to
  // back, so load that comes and goes on a shared machine falls on both sides of most differences.
  double PairedMedian(const Result& other) const {
    Result d;
    for (size_t i = 0; i < std::min(us.size(), other.us.size()); ++i) d.us.push_back(us[i] - other.us[i]);
    return d.Percentile(0.5);
  }
};

// The robots' velocities at request i: forward and angular change slowly, as a team's would.
float Forward(int i, int robot) { return static_cast<float>(0.8 * std::sin(0.05 * i + robot)); }
float Angular(int i, int robot) { return static_cast<float>(1.0 * std::cos(0.03 * i + 2 * robot)); }

std::string SyncRequest(int i) {
  ws::SimulationSyncRequest r;
  r.set_sim_step(kSimStep);
  for (int team = 0; team < 2; ++team)
    for (int k = 0; k < kCommanded; ++k) {
      ws::RobotCommand* c = r.mutable_robot_control()->add_robot_commands();
      c->set_id(static_cast<uint32_t>(16 * team + k));
      auto* v = c->mutable_move_command()->mutable_local_velocity();
      v->set_forward(Forward(i, k));
      v->set_left(0.0f);
      v->set_angular(Angular(i, k));
    }
  return r.SerializeAsString();
}

// A team on UDP: one socket, one sync request at a time.
class SyncClient {
 public:
  explicit SyncClient(uint16_t sync_port) : socket_(Bind()), to_(*turf::MakeEndpoint("127.0.0.1", sync_port)) {}

  // Until requests are answered without errors (turf-sim seen), then `warmup` more.
  void WaitReady(int warmup) {
    const auto ready_by = SteadyClock::now() + 20s;
    for (int good = 0; good < warmup;) {
      if (SteadyClock::now() > ready_by) throw std::runtime_error("turf-sim did not answer sync requests in 20 s");
      if (Ask(SyncRequest(sent_++)))
        ++good;
      else
        std::this_thread::sleep_for(10ms);
    }
  }
  // The wall time of the next request, from sending it to its response's arrival (parsed after), in us.
  double Time() {
    const std::string bytes = SyncRequest(sent_++);
    const auto start = SteadyClock::now();
    std::optional<turf::Datagram> d = Exchange(bytes);
    const auto end = SteadyClock::now();
    if (!Answered(d)) throw std::runtime_error("a sync request failed");
    last_response_ = d->bytes;
    return std::chrono::duration<double, std::micro>(end - start).count();
  }

 private:
  static turf::UdpSocket Bind() {
    std::string error;
    std::optional<turf::UdpSocket> s = turf::UdpSocket::Bind("127.0.0.1", 0, false, &error);
    if (!s) throw std::runtime_error(error);
    return std::move(*s);
  }
  std::optional<turf::Datagram> Exchange(const std::string& bytes) {
    std::string error;
    const std::vector<uint8_t> data(bytes.begin(), bytes.end());
    if (!socket_.SendTo(data, to_, &error)) throw std::runtime_error(error);
    return socket_.Receive(65536, 5s);
  }
  // A response without errors.
  static bool Answered(const std::optional<turf::Datagram>& d) {
    ws::SimulationSyncResponse r;
    return d && r.ParseFromArray(d->bytes.data(), static_cast<int>(d->bytes.size())) &&
           r.robot_control_response().errors_size() == 0;
  }
  bool Ask(const std::string& bytes) {
    std::optional<turf::Datagram> d = Exchange(bytes);
    if (!Answered(d)) return false;
    last_response_ = d->bytes;
    return true;
  }

 public:
  const std::vector<uint8_t>& last_response() const { return last_response_; }

 private:
  turf::UdpSocket socket_;
  const turf::UdpEndpoint to_;
  int sent_ = 0;
  std::vector<uint8_t> last_response_;
};

// (u) Answers every datagram with `response` on a thread of its own, as a front-end would, after `work()`.
class UdpEcho {
 public:
  UdpEcho(std::vector<uint8_t> response, std::function<void()> work)
      : socket_(turf::UdpSocket::Bind("127.0.0.1", 0, false, &error_).value()),
        response_(std::move(response)),
        work_(work),
        thread_([this] { Serve(); }) {}
  ~UdpEcho() {
    stop_.store(true);
    thread_.join();
  }
  uint16_t port() const { return socket_.LocalPort(); }

 private:
  void Serve() {
    while (!stop_.load()) {
      std::optional<turf::Datagram> d = socket_.Receive(65536, 50ms);
      if (!d) continue;
      work_();
      std::string error;
      socket_.SendTo(response_, d->from, &error);
    }
  }
  std::string error_;
  turf::UdpSocket socket_;
  const std::vector<uint8_t> response_;
  const std::function<void()> work_;
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

uint16_t FreePort() {
  std::string error;
  auto s = turf::UdpSocket::Bind("127.0.0.1", 0, false, &error);
  if (!s) throw std::runtime_error(error);
  return s->LocalPort();
}

turf::SimprotoBridgeOptions SyncOnly() {
  turf::SimprotoBridgeOptions o;
  o.listen = "127.0.0.1";
  o.control_port = o.blue_port = o.yellow_port = 0;
  o.sync_port = FreePort();
  o.sync = true;
  return o;
}

turf::SimNodeOptions NodeOptions(const std::string& qos, const std::string& tag) {
  turf::SimNodeOptions o;
  o.domain = 1 + static_cast<int>(getpid() % 99);
  o.prefix = "syncbench" + std::to_string(getpid()) + "_" + tag;
  o.qos_file = qos;
  o.mode = turf::TimeMode::kLockstep;
  return o;
}

// Runs `node.Run(stop)` on a thread until destroyed.
template <class Node>
class OnThread {
 public:
  explicit OnThread(Node& node) : thread_([this, &node] { node.Run([this] { return stop_.load(); }); }) {}
  ~OnThread() {
    stop_ = true;
    thread_.join();
  }

 private:
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

// (a) turf-sim's node and a separate bridge, each on its own DDS participant.
struct OverDds {
  static turf::SimprotoBridgeOptions BridgeOptions(const turf::SimNodeOptions& node) {
    turf::SimprotoBridgeOptions o = SyncOnly();
    o.domain = node.domain;
    o.prefix = node.prefix;
    o.qos_file = node.qos_file;
    return o;
  }
  OverDds(const turf::Scene& scene, const std::string& qos)
      : node_options(NodeOptions(qos, "dds")),
        bridge_options(BridgeOptions(node_options)),
        node(scene, node_options),
        bridge(bridge_options) {}
  const turf::SimNodeOptions node_options;
  const turf::SimprotoBridgeOptions bridge_options;
  turf::SimNode node;
  turf::SimprotoBridge bridge;
};

// (b) turf-sim with the front-end in its process (turf-sim --simproto).
struct InProcess {
  InProcess(const turf::Scene& scene, const std::string& qos, turf::SimprotoBridgeOptions o)
      : port(o.sync_port), host(scene, NodeOptions(qos, "host"), FrontEnd(std::move(o))) {}
  static turf::InProcessFrontEnds FrontEnd(turf::SimprotoBridgeOptions o) {
    turf::InProcessFrontEnds f;
    f.simproto = std::move(o);
    return f;
  }
  const uint16_t port;
  turf::SimHost host;
};

// Diagnostic: the node and the front-end on one MemoryBus, no DDS participant at all (what (b) costs without
// turf-sim also publishing on DDS).
struct MemoryOnly {
  MemoryOnly(const turf::Scene& scene, turf::SimprotoBridgeOptions o)
      : port(o.sync_port),
        bus(NodeOptions("", "memory").prefix),
        node(scene, NodeOptions("", "memory"), bus),
        bridge(std::move(o), bus) {}
  const uint16_t port;
  turf::dds::MemoryBus bus;
  turf::SimNode node;
  turf::SimprotoBridge bridge;
};

// (c) The kernel alone: each "request" applies the same commands and runs the steps the bridge's planner gives.
class PhysicsOnly {
 public:
  explicit PhysicsOnly(const turf::Scene& scene) : kernel_(scene) {}
  double Time() {
    const int i = done_++;
    const auto start = SteadyClock::now();
    for (int team = 0; team < 2; ++team)
      for (int k = 0; k < kCommanded; ++k) {
        turf::RobotCommand c;
        c.team = team == 0 ? turf::Team::kBlue : turf::Team::kYellow;
        c.id = k;
        c.move = turf::MoveKind::kLocalVelocity;
        c.velocity = {Forward(i, k), 0.0, Angular(i, k)};
        kernel_.Command(c.team, c);
      }
    const uint32_t steps =
        planner_.Plan(turf::simproto::FloatSecondsToNanoseconds(kSimStep), kernel_.world().step_ns());
    for (uint32_t s = 0; s < steps; ++s) kernel_.Step();
    return std::chrono::duration<double, std::micro>(SteadyClock::now() - start).count();
  }

 private:
  turf::SslKernel kernel_;
  turf::simproto::StepPlanner planner_;
  int done_ = 0;
};

// Every thread made after this runs on `cpu` only (threads inherit the caller's affinity).
bool PinProcessTo(int cpu) {
  cpu_set_t set;
  CPU_ZERO(&set);
  CPU_SET(cpu, &set);
  return sched_setaffinity(0, sizeof(set), &set) == 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app("turf-bench-sync: SSL sync-port round trip, separate bridge over DDS vs in turf-sim's process");
  int requests = 1000;
  int warmup = 30;
  std::string scene_path = TURF_SOURCE_DIR "/configs/scenes/ssl_div_a.yaml";
  app.add_option("--requests", requests, "timed requests to each")->capture_default_str();
  app.add_option("--warmup", warmup, "untimed requests to each before the timed ones")->capture_default_str();
  app.add_option("--scene", scene_path, "scene file")->capture_default_str();
  std::string only = "abmcu";
  app.add_option("--only", only, "rows to measure: a, b, m (b'), c, u; e.g. 'bc' under a profiler")
      ->capture_default_str();
  int cpu = -1;
  app.add_option("--cpu", cpu,
                 "run everything (client, turf-sim, front-ends, DDS) on this one core, as `taskset -c N` would; "
                 "-1: wherever the scheduler puts it")
      ->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  if (cpu >= 0 && !PinProcessTo(cpu)) {
    std::fprintf(stderr, "cannot run on cpu %d\n", cpu);
    return 2;
  }
  spdlog::set_level(spdlog::level::warn);

  turf::SceneLoadResult loaded = turf::LoadSceneFile(scene_path);
  if (!loaded.scene) {
    std::fprintf(stderr, "cannot load %s\n", scene_path.c_str());
    return 2;
  }
  const std::string qos = turf::bench::QosWithoutIntraprocess("sync");
  // All side by side, one request to each in turn (the order rotating), so that load from elsewhere on the machine
  // falls on every row alike. Idle lockstep nodes only wake every 50 ms.
  Result dds, local, memory, physics, udp;
  {
    OverDds over_dds(*loaded.scene, qos);
    InProcess in_process(*loaded.scene, qos, SyncOnly());
    MemoryOnly memory_only(*loaded.scene, SyncOnly());
    PhysicsOnly physics_only(*loaded.scene);
    OnThread<turf::SimNode> t1(over_dds.node);
    OnThread<turf::SimprotoBridge> t2(over_dds.bridge);
    OnThread<turf::SimHost> t3(in_process.host);
    OnThread<turf::SimNode> t4(memory_only.node);
    OnThread<turf::SimprotoBridge> t5(memory_only.bridge);
    SyncClient to_dds(over_dds.bridge_options.sync_port), to_host(in_process.port), to_memory(memory_only.port);
    to_dds.WaitReady(warmup);
    to_host.WaitReady(warmup);
    to_memory.WaitReady(warmup);
    for (int i = 0; i < warmup; ++i) physics_only.Time();
    const std::vector<uint8_t> response =
        !to_host.last_response().empty() ? to_host.last_response() : to_memory.last_response();
    PhysicsOnly echo_physics(*loaded.scene);
    UdpEcho echo(response, [&echo_physics] { echo_physics.Time(); });
    SyncClient to_echo(echo.port());
    to_echo.WaitReady(warmup);
    // The rows in the order of `only`'s letters "abmcu", each with what it times.
    const std::pair<Result*, std::function<double()>> rows[] = {
        {&dds, [&] { return to_dds.Time(); }},       {&local, [&] { return to_host.Time(); }},
        {&memory, [&] { return to_memory.Time(); }}, {&physics, [&] { return physics_only.Time(); }},
        {&udp, [&] { return to_echo.Time(); }},
    };
    constexpr int kRows = static_cast<int>(std::size(rows));
    for (int i = 0; i < requests; ++i)
      for (int k = 0; k < kRows; ++k) {
        const int r = (i + k) % kRows;
        if (only.find("abmcu"[r]) != std::string::npos) rows[r].first->us.push_back(rows[r].second());
      }
  }
  std::remove(qos.c_str());

  std::printf("SSL sync port, %s, sim_step 1/60 s (8.33 physics steps of 2 ms), %d robots commanded; ",
              scene_path.substr(scene_path.find_last_of('/') + 1).c_str(), 2 * kCommanded);
  std::printf("%d requests to each, in turn; ", requests);
  if (cpu >= 0)
    std::printf("everything on cpu %d of %u\n", cpu, std::thread::hardware_concurrency());
  else
    std::printf("%u cores\n", std::thread::hardware_concurrency());
  std::printf(
      "| path | mean us | p50 us | p99 us | beyond physics (c): mean / p50 us | beyond the UDP floor (u): mean / p50 "
      "us "
      "|\n");
  std::printf("| --- | --- | --- | --- | --- | --- |\n");
  auto row = [&](const char* name, const Result& r, bool overhead) {
    std::printf("| %s | %.0f | %.0f | %.0f |", name, r.Mean(), r.Percentile(0.5), r.Percentile(0.99));
    if (!overhead) return (void)std::printf(" | |\n");
    std::printf(" %.0f / %.0f |", r.Mean() - physics.Mean(), r.Percentile(0.5) - physics.Percentile(0.5));
    std::printf(" %.0f / %.0f |\n", r.Mean() - udp.Mean(), r.Percentile(0.5) - udp.Percentile(0.5));
  };
  row("(a) turf-sim + separate bridge over Fast DDS", dds, true);
  row("(b) turf-sim --simproto (in process)", local, true);
  row("(b') node and front-end on one MemoryBus, no DDS at all", memory, true);
  row("(c) physics alone (SslKernel::Step)", physics, false);
  row("(u) UDP floor: (c) served over UDP by a bare thread", udp, true);
  // On a loaded machine the means and medians above carry other processes' time slices; the lower quantiles and
  // the paired differences much less so.
  std::printf(
      "\n| path | p10 us | p25 us | beyond physics (c), median of paired differences us | beyond (u), same us |\n");
  std::printf("| --- | --- | --- | --- | --- |\n");
  auto low = [&](const char* name, const Result& r) {
    std::printf("| %s | %.0f | %.0f | %.0f | %.0f |\n", name, r.Percentile(0.1), r.Percentile(0.25),
                r.PairedMedian(physics), r.PairedMedian(udp));
  };
  low("(a)", dds);
  low("(b)", local);
  low("(b')", memory);
  low("(c)", physics);
  low("(u)", udp);
  return 0;
}
