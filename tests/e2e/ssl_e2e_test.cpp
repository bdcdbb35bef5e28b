// End to end with real processes on loopback: turf-sim, turf-grsim-bridge,
// turf-vision-bridge and turf-simproto-bridge, driven by a test client that
// speaks the legacy protocols with its own protos (tests/e2e/proto), as an SSL
// team's software would. Every test has its own DDS domain, topic prefix and
// UDP ports, so tests can run in parallel.
#include <arpa/inet.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>
#include "tests/test_domain.h"

#include <chrono>
#include <cmath>
#include <map>
#include <optional>
#include <string>
#include <thread>

#include "tests/e2e/child_process.h"
#include "tests/e2e/proto/team_grsim.pb.h"
#include "tests/e2e/proto/team_simulation.pb.h"
#include "tests/e2e/proto/team_vision.pb.h"

namespace turf::test {
namespace {

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
      team::vision::SSL_WrapperPacket p;
      if (!p.ParseFromString(*bytes)) {
        ++unparseable;
        continue;
      }
      if (p.has_geometry()) geometry = p.geometry();
      if (!p.has_detection()) continue;
      const auto& d = p.detection();
      ++frames;
      cameras[d.camera_id()] = d.frame_number();
      if (d.t_sent() < d.t_capture() || d.t_capture() <= 0) ++bad_times;
      send_delays.push_back(d.t_sent() - d.t_capture());
      for (const auto& r : d.robots_blue()) robots[{0, r.robot_id()}] = {r.x(), r.y(), r.orientation(), d.t_capture()};
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
  std::optional<team::vision::SSL_GeometryData> geometry;
  Seen ball;
  std::vector<Seen> ball_track;
  std::vector<double> send_delays;  // t_sent - t_capture of every detection
  int frames = 0, unparseable = 0, bad_times = 0;

 private:
  Udp udp_;
};

int g_match = 0;

// turf-sim and the three SSL bridges as separate processes.
class Match {
 public:
  Match() {
    domain = TestDomain(g_match);
    prefix = "e2e" + std::to_string(getpid()) + "_" + std::to_string(g_match++);
    grsim_port = FreeUdpPort();
    vision_port = FreeUdpPort();
    blue_status_port = FreeUdpPort();
    yellow_status_port = FreeUdpPort();
    control_port = FreeUdpPort();
    blue_port = FreeUdpPort();
    yellow_port = FreeUdpPort();
    sync_port = FreeUdpPort();
    const std::vector<std::string> dds = {"--domain", std::to_string(domain), "--prefix", prefix};
    sim = std::make_unique<ChildProcess>(
        prefix + "_sim",
        Args("participants/sim/turf-sim",
             {"--scene", std::string(TURF_SOURCE_DIR) + "/configs/scenes/ssl_div_a.yaml", "--speed", "1"}, dds));
    grsim = std::make_unique<ChildProcess>(
        prefix + "_grsim",
        Args("participants/grsim_bridge/turf-grsim-bridge",
             {"--listen", "127.0.0.1", "--port", std::to_string(grsim_port), "--blue-status-port",
              std::to_string(blue_status_port), "--yellow-status-port", std::to_string(yellow_status_port)},
             dds));
    vision = std::make_unique<ChildProcess>(
        prefix + "_vision", Args("participants/vision_bridge/turf-vision-bridge",
                                 // Simulation-time stamps: speeds measured from the stream stay
                                 // right when a loaded machine runs the simulation slower than real time.
                                 {"--address", "127.0.0.1", "--port", std::to_string(vision_port), "--geometry-every",
                                  "30", "--clock", "sim"},
                                 dds));
    simproto = std::make_unique<ChildProcess>(
        prefix + "_simproto", Args("participants/simproto_bridge/turf-simproto-bridge",
                                   {"--listen", "127.0.0.1", "--control-port", std::to_string(control_port),
                                    "--blue-port", std::to_string(blue_port), "--yellow-port",
                                    std::to_string(yellow_port), "--sync-port", std::to_string(sync_port)},
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
  std::unique_ptr<ChildProcess> sim, grsim, vision, simproto;

 private:
  static std::vector<std::string> Args(const std::string& bin, std::vector<std::string> args,
                                       const std::vector<std::string>& dds) {
    args.insert(args.begin(), BuiltBinary(bin));
    args.insert(args.end(), dds.begin(), dds.end());
    return args;
  }
};

std::string GrsimMove(bool yellow, int id, double forward, double left, double angular, double kick = 0) {
  team::grsim::grSim_Packet p;
  auto* c = p.mutable_commands();
  c->set_timestamp(0);
  c->set_isteamyellow(yellow);
  auto* r = c->add_robot_commands();
  r->set_id(id);
  r->set_kickspeedx(static_cast<float>(kick));
  r->set_kickspeedz(0);
  r->set_veltangent(static_cast<float>(forward));
  r->set_velnormal(static_cast<float>(left));
  r->set_velangular(static_cast<float>(angular));
  r->set_spinner(false);
  r->set_wheelsspeed(false);
  return p.SerializeAsString();
}

std::string GrsimPlace(bool yellow, int id, double x, double y, double dir_deg, std::optional<double> ball_x = {},
                       double ball_y = 0) {
  team::grsim::grSim_Packet p;
  auto* rep = p.mutable_replacement();
  auto* r = rep->add_robots();
  r->set_x(x);
  r->set_y(y);
  r->set_dir(dir_deg);
  r->set_id(id);
  r->set_yellowteam(yellow);
  r->set_turnon(true);
  if (ball_x) {
    rep->mutable_ball()->set_x(*ball_x);
    rep->mutable_ball()->set_y(ball_y);
    rep->mutable_ball()->set_vx(0);
    rep->mutable_ball()->set_vy(0);
  }
  return p.SerializeAsString();
}

// Waits until the vision stream runs (all bridges found turf-sim).
void WaitForVision(Match& m, VisionClient& v) {
  const auto end = Clock::now() + 15s;
  while (Clock::now() < end && (v.cameras.size() < 4 || !v.geometry)) v.Drain(100ms);
  ASSERT_TRUE(m.AllRunning());
  ASSERT_EQ(v.cameras.size(), 4u) << m.vision->Log();
  ASSERT_TRUE(v.geometry.has_value());
}

// Sends a command at ~60 Hz until the robot's vision stamps (simulation time)
// have advanced by `sim_seconds` from now: waits hold on a slow machine.
std::optional<Seen> KeepFor(Udp& team, const std::string& packet, int port, VisionClient& v, int team_id, int id,
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

// Sends a command repeatedly at ~60 Hz (as a team does) while draining vision.
void Keep(Udp& team, const std::string& packet, int port, VisionClient& v, std::chrono::milliseconds duration) {
  const auto end = Clock::now() + duration;
  while (Clock::now() < end) {
    team.Send(packet, port);
    v.Drain(16ms);
  }
}

TEST(SslEndToEnd, GrsimCommandMovesRobotAtCommandedSpeedInVision) {
  Match m;
  VisionClient v(m.vision_port);
  WaitForVision(m, v);
  Udp team;
  // A free lane of the kick-off formation: y = 2 m, from x = -3 m towards the halfway line.
  Keep(team, GrsimPlace(false, 3, -3.0, 2.0, 0.0), m.grsim_port, v, 300ms);
  // Through the 1/3 s ramp, then measure over 0.8 s, all in simulation time.
  const auto a = KeepFor(team, GrsimMove(false, 3, 1.0, 0.0, 0.0), m.grsim_port, v, 0, 3, 0.6);
  const auto b = KeepFor(team, GrsimMove(false, 3, 1.0, 0.0, 0.0), m.grsim_port, v, 0, 3, 0.8);
  ASSERT_TRUE(a && b);
  const double speed = (b->x - a->x) / 1000.0 / (b->t - a->t);
  EXPECT_NEAR(speed, 1.0, 0.05);
  EXPECT_NEAR(b->y, 2000.0, 10.0);
  EXPECT_EQ(v.bad_times, 0);
  EXPECT_EQ(v.unparseable, 0);
  EXPECT_EQ(v.geometry->field().field_length(), 12000);
}

TEST(SslEndToEnd, ReplacementPlacesBallAndRobots) {
  Match m;
  VisionClient v(m.vision_port);
  WaitForVision(m, v);
  Udp team;
  team.Send(GrsimPlace(true, 4, 2.0, -1.5, 90.0, 1.0, 2.0), m.grsim_port);
  v.Drain(500ms);
  const auto r = v.Robot(1, 4);
  ASSERT_TRUE(r);
  EXPECT_NEAR(r->x, 2000.0, 5.0);
  EXPECT_NEAR(r->y, -1500.0, 5.0);
  EXPECT_NEAR(r->orientation, M_PI / 2, 0.01);
  EXPECT_NEAR(v.ball.x, 1000.0, 5.0);
  EXPECT_NEAR(v.ball.y, 2000.0, 5.0);
}

TEST(SslEndToEnd, KickGivesTheBallTheCommandedSpeed) {
  Match m;
  VisionClient v(m.vision_port);
  WaitForVision(m, v);
  Udp team;
  // Robot at (1, 0) facing +x, ball resting against its front face.
  Keep(team, GrsimPlace(false, 5, 1.0, 0.0, 0.0, 1.0 + 0.08 + 0.0215 + 0.002, 0.0), m.grsim_port, v, 300ms);
  v.ball_track.clear();
  Keep(team, GrsimMove(false, 5, 0.0, 0.0, 0.0, 4.0), m.grsim_port, v, 400ms);
  // Ball speed over the first 0.1 s of its flight, from the vision stream.
  size_t i = 0;
  while (i + 1 < v.ball_track.size() && v.ball_track[i + 1].x - v.ball_track[i].x < 1.0) ++i;
  size_t j = i + 1;
  while (j < v.ball_track.size() && v.ball_track[j].t - v.ball_track[i].t < 0.05) ++j;
  ASSERT_LT(j, v.ball_track.size()) << "the ball never moved";
  // The mean speed over [t_i, t_j] plus the sliding deceleration (the scene's
  // 3 m/s^2) over half the window is the speed at t_i, however many frames a
  // loaded machine dropped in between.
  const double dt = v.ball_track[j].t - v.ball_track[i].t;
  const double speed = (v.ball_track[j].x - v.ball_track[i].x) / 1000.0 / dt + 3.0 * dt / 2;
  EXPECT_NEAR(speed, 4.0, 0.3);
}

TEST(SslEndToEnd, StatusPacketsArriveOnTheTeamsPort) {
  Match m;
  VisionClient v(m.vision_port);
  WaitForVision(m, v);
  Udp team;
  Udp blue_status(m.blue_status_port);
  Udp yellow_status(m.yellow_status_port);
  // The status goes to the address that sent the team's commands: send some first.
  Keep(team, GrsimMove(false, 6, 0.0, 0.0, 0.0), m.grsim_port, v, 200ms);
  Keep(team, GrsimPlace(false, 6, -1.0, -1.0, 0.0, -1.0 + 0.08 + 0.0215 + 0.002, -1.0), m.grsim_port, v, 300ms);
  bool infrared = false;
  const auto end = Clock::now() + 3s;
  while (Clock::now() < end && !infrared) {
    team.Send(GrsimMove(false, 6, 0.0, 0.0, 0.0), m.grsim_port);
    if (auto bytes = blue_status.Receive()) {
      team::grsim::Robots_Status status;
      ASSERT_TRUE(status.ParseFromString(*bytes));
      for (const auto& s : status.robots_status()) infrared = infrared || (s.robot_id() == 6 && s.infrared());
    }
  }
  EXPECT_TRUE(infrared);
  EXPECT_FALSE(yellow_status.Receive().has_value());
}

std::string SimprotoMove(int id, double forward) {
  team::simulation::RobotControl rc;
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
// been faster) it answers "not available": ask again then.
std::optional<team::simulation::SimulatorResponse> Command(Udp& team, const team::simulation::SimulatorCommand& cmd,
                                                           uint16_t port) {
  const auto give_up = Clock::now() + 15s;
  while (Clock::now() < give_up) {
    team.Send(cmd.SerializeAsString(), port);
    team::simulation::SimulatorResponse response;
    bool answered = false;
    const auto answer_by = Clock::now() + 5s;  // the bridge's reply timeout is 2 s
    while (Clock::now() < answer_by && !answered)
      if (auto bytes = team.Receive()) answered = response.ParseFromString(*bytes);
    if (!answered) return std::nullopt;
    const bool not_yet =
        response.errors_size() > 0 && response.errors(0).message().find("has not been seen yet") != std::string::npos;
    if (!not_yet) return response;
    std::this_thread::sleep_for(200ms);
  }
  return std::nullopt;
}

TEST(SslEndToEnd, SimulationProtocolMovesOnlyItsOwnTeam) {
  Match m;
  VisionClient v(m.vision_port);
  WaitForVision(m, v);
  Udp team;
  // Teleport blue 2 and yellow 2 through the control port.
  team::simulation::SimulatorCommand cmd;
  for (auto [team_id, y] : {std::pair{team::simulation::BLUE, 2.0f}, std::pair{team::simulation::YELLOW, -2.0f}}) {
    auto* t = cmd.mutable_control()->add_teleport_robot();
    t->mutable_id()->set_id(2);
    t->mutable_id()->set_team(team_id);
    t->set_x(-3.0f);
    t->set_y(y);
    t->set_orientation(0.0f);
    t->set_present(true);
  }
  const auto placed = Command(team, cmd, m.control_port);
  ASSERT_TRUE(placed);
  ASSERT_EQ(placed->errors_size(), 0) << placed->errors(0).message();
  const auto placed_by = Clock::now() + 5s;
  do {
    v.Drain(50ms);
  } while (Clock::now() < placed_by && !(v.Robot(1, 2) && std::abs(v.Robot(1, 2)->x + 3000.0) < 5.0));
  v.Drain(100ms);
  const auto yellow_before = v.Robot(1, 2);
  ASSERT_TRUE(yellow_before);
  EXPECT_NEAR(yellow_before->x, -3000.0, 5.0);
  // The blue port commands blue 2 only.
  const auto a = KeepFor(team, SimprotoMove(2, 1.0), m.blue_port, v, 0, 2, 0.6);
  const auto b = KeepFor(team, SimprotoMove(2, 1.0), m.blue_port, v, 0, 2, 0.8);
  ASSERT_TRUE(a && b);
  EXPECT_NEAR((b->x - a->x) / 1000.0 / (b->t - a->t), 1.0, 0.05);
  const auto yellow_after = v.Robot(1, 2);
  EXPECT_NEAR(yellow_after->x, yellow_before->x, 1.0);
  EXPECT_NEAR(yellow_after->y, yellow_before->y, 1.0);
  // Every commanded robot gets feedback.
  team.Send(SimprotoMove(2, 0.0), m.blue_port);
  bool feedback = false;
  for (int i = 0; i < 50 && !feedback; ++i) {
    if (auto bytes = team.Receive()) {
      team::simulation::RobotControlResponse r;
      if (r.ParseFromString(*bytes))
        for (const auto& f : r.feedback()) feedback = feedback || (f.id() == 2 && f.has_dribbler_ball_contact());
    }
  }
  EXPECT_TRUE(feedback);
}

TEST(SslEndToEnd, ErForceRealismKnobsChangeTheVisionStream) {
  Match m;
  VisionClient v(m.vision_port);
  WaitForVision(m, v);
  Udp team;
  team::simulation::RealismConfigErForce knobs;
  knobs.set_vision_processing_time(20'000'000);  // ns
  knobs.set_stddev_robot_p(0.01f);               // m
  team::simulation::SimulatorCommand cmd;
  auto* any = cmd.mutable_config()->mutable_realism_config()->add_custom();
  any->set_type_url("type.googleapis.com/sslsim.RealismConfigErForce");
  any->set_value(knobs.SerializeAsString());
  const auto answer = Command(team, cmd, m.control_port);
  ASSERT_TRUE(answer);
  const team::simulation::SimulatorResponse& response = *answer;
  EXPECT_EQ(response.errors_size(), 0) << response.errors(0).code() << ": " << response.errors(0).message();
  // Now every detection left the vision system 20 ms after its capture, and
  // standing robots jitter by about a centimetre.
  v.robots.clear();
  v.send_delays.clear();
  std::vector<double> xs;
  // 400 detections (about 0.4 s of simulation time), however fast the machine.
  const auto end = Clock::now() + 20s;
  int delayed = 0, frames = 0;
  while (Clock::now() < end && v.send_delays.size() < 400) {
    v.Drain(50ms);
    if (auto r = v.Robot(0, 10)) xs.push_back(r->x);
  }
  for (double dt : v.send_delays) {
    ++frames;
    delayed += std::abs(dt - 0.020) < 0.0005;
  }
  ASSERT_GT(frames, 100);
  EXPECT_GT(delayed, frames * 9 / 10);
  double mean = 0, ss = 0;
  for (double x : xs) mean += x / xs.size();
  for (double x : xs) ss += (x - mean) * (x - mean);
  EXPECT_GT(std::sqrt(ss / xs.size()), 3.0);  // mm
}

TEST(SslEndToEnd, BadDatagramsChangeNothing) {
  Match m;
  VisionClient v(m.vision_port);
  WaitForVision(m, v);
  Udp team;
  Keep(team, GrsimPlace(false, 7, 0.5, 4.0, 0.0), m.grsim_port, v, 300ms);  // a free lane
  const auto before = v.Robot(0, 7);
  ASSERT_TRUE(before);
  const std::string valid = GrsimMove(false, 7, 1.0, 0.0, 0.0);
  const std::string nan = GrsimMove(false, 7, NAN, 0.0, 0.0);
  const std::string huge_id = GrsimMove(false, 99, 1.0, 0.0, 0.0);
  const std::string garbage = "\xff\xfe\x01\x02 not a protobuf at all \x80\x80\x80";
  const std::string oversized(70000, 'x');
  const auto end = Clock::now() + 1500ms;
  while (Clock::now() < end) {
    team.Send(nan, m.grsim_port);
    team.Send(huge_id, m.grsim_port);
    team.Send(garbage, m.grsim_port);
    team.Send(valid.substr(0, valid.size() / 2), m.grsim_port);  // truncated
    team.Send(oversized.substr(0, 60000), m.grsim_port);
    team.Send(garbage, m.blue_port);
    team.Send(SimprotoMove(7, NAN), m.blue_port);
    team.Send(garbage, m.control_port);
    v.Drain(16ms);
  }
  const auto after = v.Robot(0, 7);
  ASSERT_TRUE(after);
  EXPECT_NEAR(after->x, before->x, 1.0);
  EXPECT_NEAR(after->y, before->y, 1.0);
  EXPECT_TRUE(m.AllRunning());
  // And the bridges still work afterwards.
  Keep(team, valid, m.grsim_port, v, 1000ms);
  EXPECT_GT(v.Robot(0, 7)->x - after->x, 200.0);
}

}  // namespace
}  // namespace turf::test
