// What the SSL end-to-end tests share: turf-sim and the three SSL bridges as
// real processes on loopback (Match), and a team client in the test process that
// speaks the legacy protocols over UDP, as an SSL team's software would (with
// turf's protos: the wire is pinned by the codecs' golden-byte tests). Every
// Match has its own DDS domain, topic prefix and UDP ports, so tests can run in
// parallel. Waits are in simulation time (vision stamps with --clock sim) with a
// wall-clock deadline of at most 20 s.
#pragma once

#include <arpa/inet.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "codecs/proto/grsim.pb.h"
#include "codecs/proto/ssl_simulation.pb.h"
#include "codecs/proto/ssl_vision.pb.h"
#include "tests/support/process.h"
#include "tests/support/team_packets.h"
#include "tests/test_domain.h"

namespace turf::test {

using namespace std::chrono_literals;
using Clock = std::chrono::steady_clock;

// A plain UDP socket on 127.0.0.1, as team software would open one.
class Udp {
 public:
  explicit Udp(int port = 0) {
    fd_ = socket(AF_INET, SOCK_DGRAM, 0);
    sockaddr_in a = Addr(port);
    bind(fd_, reinterpret_cast<sockaddr*>(&a), sizeof(a));
    timeval tv{0, 20000};
    setsockopt(fd_, SOL_SOCKET, SO_RCVTIMEO, &tv, sizeof(tv));
  }
  ~Udp() { close(fd_); }
  void Send(const std::string& bytes, int port) {
    sockaddr_in a = Addr(port);
    sendto(fd_, bytes.data(), bytes.size(), 0, reinterpret_cast<sockaddr*>(&a), sizeof(a));
  }
  std::optional<std::string> Receive() {
    char buf[65536];
    const ssize_t n = recv(fd_, buf, sizeof(buf), 0);
    if (n < 0) return std::nullopt;
    return std::string(buf, static_cast<size_t>(n));
  }

 private:
  static sockaddr_in Addr(int port) {
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    a.sin_port = htons(static_cast<uint16_t>(port));
    return a;
  }
  int fd_;
};

struct Seen {
  double x = 0, y = 0, orientation = 0, t = 0;  // mm, rad, s (t_capture)
};

// The SSL-Vision stream as a team decodes it.
class VisionClient {
 public:
  explicit VisionClient(int port) : udp_(port) {}
  // Reads everything available for `duration`.
  void Drain(std::chrono::milliseconds duration) {
    const auto end = Clock::now() + duration;
    while (Clock::now() < end) {
      auto bytes = udp_.Receive();
      if (!bytes) continue;
      wire::vision::SSL_WrapperPacket p;
      if (!p.ParseFromString(*bytes)) {
        ++unparseable;
        continue;
      }
      if (p.has_geometry()) geometry = p.geometry();
      if (!p.has_detection()) continue;
      const auto& d = p.detection();
      ++frames;
      latest_t = std::max(latest_t, d.t_capture());
      cameras[d.camera_id()] = d.frame_number();
      if (d.t_sent() < d.t_capture() || d.t_capture() <= 0) ++bad_times;
      send_delays.push_back(d.t_sent() - d.t_capture());
      capture_times.push_back(d.t_capture());
      for (const auto& r : d.robots_blue()) {
        robots[{0, r.robot_id()}] = {r.x(), r.y(), r.orientation(), d.t_capture()};
        blue_tracks[r.robot_id()].push_back(robots[{0, r.robot_id()}]);
      }
      for (const auto& r : d.robots_yellow())
        robots[{1, r.robot_id()}] = {r.x(), r.y(), r.orientation(), d.t_capture()};
      for (const auto& b : d.balls()) {
        ball = {b.x(), b.y(), 0, d.t_capture()};
        ball_track.push_back(ball);
      }
    }
  }
  std::optional<Seen> Robot(int team, int id) const {
    auto it = robots.find({team, id});
    if (it == robots.end()) return std::nullopt;
    return it->second;
  }

  std::map<std::pair<int, uint32_t>, Seen> robots;
  std::map<uint32_t, uint32_t> cameras;  // camera id -> last frame number
  std::optional<wire::vision::SSL_GeometryData> geometry;
  Seen ball;
  std::vector<Seen> ball_track;
  std::vector<double> send_delays;                    // t_sent - t_capture of every detection
  std::vector<double> capture_times;                  // t_capture of every detection, as send_delays
  std::map<uint32_t, std::vector<Seen>> blue_tracks;  // every detection of each blue robot
  double latest_t = 0;                                // the newest t_capture seen (s)
  int frames = 0, unparseable = 0, bad_times = 0;

 private:
  Udp udp_;
};

inline int g_match = 0;

// turf-sim and the three SSL bridges as separate processes.
struct MatchOptions {
  std::string realism;  // turf-sim --realism (empty: the scene's)
  double speed = 1.0;   // turf-sim --speed
};

class Match {
 public:
  explicit Match(const MatchOptions& options = {}) {
    domain = TestDomain(g_match);
    prefix = "e2e" + std::to_string(getpid()) + "_" + std::to_string(g_match++);
    grsim_port = FreePort();
    vision_port = FreePort();
    blue_status_port = FreePort();
    yellow_status_port = FreePort();
    control_port = FreePort();
    blue_port = FreePort();
    yellow_port = FreePort();
    sync_port = FreePort();
    const std::vector<std::string> dds = {"--domain", std::to_string(domain), "--prefix", prefix};
    sim = std::make_unique<Process>(prefix + "_sim", Args("participants/sim/turf-sim", SimArgs(options), dds));
    grsim = std::make_unique<Process>(
        prefix + "_grsim",
        Args("participants/grsim_bridge/turf-grsim-bridge",
             {"--listen", "127.0.0.1", "--port", std::to_string(grsim_port), "--blue-status-port",
              std::to_string(blue_status_port), "--yellow-status-port", std::to_string(yellow_status_port)},
             dds));
    vision = std::make_unique<Process>(
        prefix + "_vision", Args("participants/vision_bridge/turf-vision-bridge",
                                 // Simulation-time stamps: speeds measured from the stream stay
                                 // right when a loaded machine runs the simulation slower than real time.
                                 {"--address", "127.0.0.1", "--port", std::to_string(vision_port), "--geometry-every",
                                  "30", "--clock", "sim"},
                                 dds));
    simproto = std::make_unique<Process>(
        prefix + "_simproto", Args("participants/simproto_bridge/turf-simproto-bridge",
                                   {"--listen", "127.0.0.1", "--control-port", std::to_string(control_port),
                                    "--blue-port", std::to_string(blue_port), "--yellow-port",
                                    std::to_string(yellow_port), "--sync-port", std::to_string(sync_port), "--sync"},
                                   dds));
  }
  ~Match() {
    // Each process must shut down cleanly on SIGTERM.
    for (auto* p : {simproto.get(), vision.get(), grsim.get(), sim.get()}) {
      const int status = p->Stop();
      EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << p->log_path() << ":\n" << p->Log();
    }
  }
  bool AllRunning() { return sim->Running() && grsim->Running() && vision->Running() && simproto->Running(); }

  int domain;
  std::string prefix;
  int grsim_port, vision_port, blue_status_port, yellow_status_port, control_port, blue_port, yellow_port, sync_port;
  std::unique_ptr<Process> sim, grsim, vision, simproto;

 private:
  static std::vector<std::string> SimArgs(const MatchOptions& options) {
    std::vector<std::string> args = {"--scene", std::string(TURF_SOURCE_DIR) + "/configs/scenes/ssl_div_a.yaml",
                                     "--speed", std::to_string(options.speed)};
    if (!options.realism.empty()) args.insert(args.end(), {"--realism", options.realism});
    return args;
  }
  static std::vector<std::string> Args(const std::string& bin, std::vector<std::string> args,
                                       const std::vector<std::string>& dds) {
    args.insert(args.begin(), Built(bin));
    args.insert(args.end(), dds.begin(), dds.end());
    return args;
  }
};

inline std::string SimprotoMove(int id, double forward) {
  wire::simulation::RobotControl rc;
  auto* c = rc.add_robot_commands();
  c->set_id(id);
  auto* v = c->mutable_move_command()->mutable_local_velocity();
  v->set_forward(static_cast<float>(forward));
  v->set_left(0);
  v->set_angular(0);
  return rc.SerializeAsString();
}

// Sends a SimulatorCommand to the control port and returns the response.
// Until the simulation bridge has seen turf-sim (the vision bridge may have
// been faster) it answers "not available", and when turf-sim's reply is late
// "did not answer": ask again then.
inline std::optional<wire::simulation::SimulatorResponse> Command(Udp& team,
                                                                  const wire::simulation::SimulatorCommand& cmd,
                                                                  uint16_t port) {
  const auto give_up = Clock::now() + 15s;
  while (Clock::now() < give_up) {
    team.Send(cmd.SerializeAsString(), port);
    wire::simulation::SimulatorResponse response;
    bool answered = false;
    const auto answer_by = Clock::now() + 5s;  // the bridge's reply timeout is 2 s
    while (Clock::now() < answer_by && !answered)
      if (auto bytes = team.Receive()) answered = response.ParseFromString(*bytes);
    if (!answered) return std::nullopt;
    // Asked too early, or turf-sim (starved on a loaded machine) answered the
    // bridge late: ask again, as team software would. Commands are idempotent.
    auto says = [&](const char* what) {
      return response.errors_size() > 0 && response.errors(0).message().find(what) != std::string::npos;
    };
    if (!says("has not been seen yet") && !says("did not answer within")) return response;
    std::this_thread::sleep_for(200ms);
  }
  return std::nullopt;
}

// Waits until the vision stream runs (all bridges found turf-sim).
inline void WaitForVision(Match& m, VisionClient& v) {
  const auto end = Clock::now() + 15s;
  while (Clock::now() < end && (v.cameras.size() < 4 || !v.geometry)) v.Drain(100ms);
  ASSERT_TRUE(m.AllRunning());
  ASSERT_EQ(v.cameras.size(), 4u) << m.vision->Log();
  ASSERT_TRUE(v.geometry.has_value());
}

// Sends a command at ~60 Hz until the robot's vision stamps (simulation time)
// have advanced by `sim_seconds` from now: waits hold on a slow machine.
inline std::optional<Seen> KeepFor(Udp& team, const std::string& packet, int port, VisionClient& v, int team_id, int id,
                                   double sim_seconds) {
  const auto start = v.Robot(team_id, id);
  const auto end = Clock::now() + 20s;
  while (Clock::now() < end) {
    team.Send(packet, port);
    v.Drain(16ms);
    const auto now = v.Robot(team_id, id);
    if (start && now && now->t - start->t >= sim_seconds) return now;
  }
  return std::nullopt;
}

// Sends `packet` at ~60 Hz (as a team does) until `done(v)` holds; false if it
// does not within 20 s.
inline bool KeepUntil(Udp& team, const std::string& packet, int port, VisionClient& v,
                      const std::function<bool(const VisionClient&)>& done) {
  const auto end = Clock::now() + 20s;
  while (Clock::now() < end) {
    team.Send(packet, port);
    v.Drain(16ms);
    if (done(v)) return true;
  }
  return false;
}

// Sends `packet` at ~60 Hz until vision's simulation time has advanced by
// `sim_seconds`; false if it does not within 20 s.
inline bool KeepForSim(Udp& team, const std::string& packet, int port, VisionClient& v, double sim_seconds) {
  const double until = v.latest_t + sim_seconds;
  return KeepUntil(team, packet, port, v, [&](const VisionClient& c) { return c.latest_t >= until; });
}

// Sends a placement (a replacement or teleport) once, then again every second
// until vision shows `placed(v)`; false if it does not within 15 s.
inline bool PlaceAndWait(Udp& team, const std::string& packet, int port, VisionClient& v,
                         const std::function<bool(const VisionClient&)>& placed) {
  const auto end = Clock::now() + 15s;
  while (Clock::now() < end) {
    team.Send(packet, port);
    const auto resend = std::min(end, Clock::now() + 1s);
    while (Clock::now() < resend) {
      v.Drain(16ms);
      if (placed(v)) return true;
    }
  }
  return false;
}

// True when vision shows the robot within `tolerance` mm of (x, y) m.
inline bool RobotSeenAt(const VisionClient& v, int team_id, int id, double x, double y, double tolerance = 5.0) {
  const auto r = v.Robot(team_id, id);
  return r && std::hypot(r->x - x * 1000.0, r->y - y * 1000.0) < tolerance;
}

// True when the newest ball detection is within `tolerance` mm of (x, y) m.
inline bool BallSeenAt(const VisionClient& v, double x, double y, double tolerance = 5.0) {
  return !v.ball_track.empty() && std::hypot(v.ball.x - x * 1000.0, v.ball.y - y * 1000.0) < tolerance;
}

}  // namespace turf::test
