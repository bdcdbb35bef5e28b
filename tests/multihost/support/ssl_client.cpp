#include "tests/multihost/support/ssl_client.h"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>

#include "codecs/proto/ssl_vision.pb.h"
#include "tests/support/team_packets.h"

namespace turf::test {

namespace {

sockaddr_in Address(const std::string& ip, int port) {
  sockaddr_in a{};
  a.sin_family = AF_INET;
  inet_pton(AF_INET, ip.c_str(), &a.sin_addr);
  a.sin_port = htons(static_cast<uint16_t>(port));
  return a;
}

}  // namespace

UdpSocket::UdpSocket(const std::string& ip, int port) {
  fd_ = socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
  const sockaddr_in a = Address(ip, port);
  if (fd_ >= 0 && bind(fd_, reinterpret_cast<const sockaddr*>(&a), sizeof(a)) != 0) {
    close(fd_);
    fd_ = -1;
    return;
  }
  timeval tv{0, 20000};
  setsockopt(fd_, SOL_SOCKET, SO_RCVTIMEO, &tv, sizeof(tv));
}

UdpSocket::~UdpSocket() {
  if (fd_ >= 0) close(fd_);
}

void UdpSocket::Send(const std::string& bytes, const std::string& ip, int port) {
  const sockaddr_in a = Address(ip, port);
  sendto(fd_, bytes.data(), bytes.size(), 0, reinterpret_cast<const sockaddr*>(&a), sizeof(a));
}

std::optional<std::string> UdpSocket::Receive() {
  char buf[65536];
  const ssize_t n = recv(fd_, buf, sizeof(buf), 0);
  if (n < 0) return std::nullopt;
  return std::string(buf, static_cast<size_t>(n));
}

bool VisionClient::ReadOne() {
  const auto bytes = socket_.Receive();
  if (!bytes) return false;
  wire::vision::SSL_WrapperPacket p;
  if (!p.ParseFromString(*bytes)) return true;
  if (p.has_geometry()) geometry = true;
  if (!p.has_detection()) return true;
  const auto& d = p.detection();
  ++detections;
  last_detection = SteadyClock::now();
  const auto seen = cameras.find(d.camera_id());
  if (seen != cameras.end() && d.frame_number() > seen->second + 1)
    longest_gap = std::max(longest_gap, d.frame_number() - seen->second - 1);
  cameras[d.camera_id()] = d.frame_number();
  for (const auto& r : d.robots_blue())
    robots_[{false, r.robot_id()}] = {r.x(), r.y(), d.t_capture(), d.frame_number()};
  for (const auto& r : d.robots_yellow())
    robots_[{true, r.robot_id()}] = {r.x(), r.y(), d.t_capture(), d.frame_number()};
  return true;
}

void VisionClient::Drain(std::chrono::milliseconds duration) {
  const auto end = SteadyClock::now() + duration;
  while (SteadyClock::now() < end) ReadOne();
}

std::optional<std::chrono::milliseconds> VisionClient::UntilDetection(std::chrono::milliseconds timeout) {
  const auto start = SteadyClock::now();
  const int before = detections;
  while (SteadyClock::now() - start < timeout) {
    ReadOne();
    if (detections > before) return std::chrono::duration_cast<std::chrono::milliseconds>(*last_detection - start);
  }
  return std::nullopt;
}

bool VisionClient::WaitForStream(size_t n, std::chrono::milliseconds timeout) {
  const auto end = SteadyClock::now() + timeout;
  while (SteadyClock::now() < end && (cameras.size() < n || !geometry)) ReadOne();
  return cameras.size() >= n && geometry;
}

std::optional<Seen> VisionClient::Robot(bool yellow, uint32_t id) const {
  auto it = robots_.find({yellow, id});
  if (it == robots_.end()) return std::nullopt;
  return it->second;
}

void KeepSending(UdpSocket& team, const std::string& packet, const std::string& ip, int port, VisionClient& vision,
                 std::chrono::milliseconds duration) {
  const auto end = SteadyClock::now() + duration;
  while (SteadyClock::now() < end) {
    team.Send(packet, ip, port);
    vision.Drain(std::chrono::milliseconds(16));
  }
}

bool SendUntil(UdpSocket& team, const std::string& packet, const std::string& ip, int port, VisionClient& vision,
               const std::function<bool()>& done, std::chrono::milliseconds timeout) {
  const auto end = SteadyClock::now() + timeout;
  while (!done()) {
    if (SteadyClock::now() > end) return false;
    team.Send(packet, ip, port);
    vision.Drain(std::chrono::milliseconds(16));
  }
  return true;
}

std::optional<double> DriveBlueRobot(UdpSocket& team, const std::string& ip, int port, VisionClient& vision, int id,
                                     double x, double y, std::chrono::milliseconds drive) {
  using std::chrono::seconds;         // deadlines, not paces: a loaded machine with DDS Security can take many seconds
  constexpr double kCameraHz = 60.0;  // the SSL scenes' camera rate
  const auto robot = [&] { return vision.Robot(false, static_cast<uint32_t>(id)); };
  // Seen `frames` captures after `since` (simulation time, whatever the pace).
  const auto later = [&](const Seen& since, uint32_t frames) {
    return [&robot, &since, frames] {
      const auto now = robot();
      return now && now->frame >= since.frame + frames;
    };
  };
  const bool placed = SendUntil(
      team, GrsimPlace(false, id, x, y, 0.0), ip, port, vision,
      [&] {
        const auto now = robot();
        return now && std::hypot(now->x / 1000.0 - x, now->y / 1000.0 - y) < 0.05;
      },
      seconds(30));
  if (!placed) return std::nullopt;
  const Seen at_place = *robot();
  // Standing still for 0.1 s.
  if (!SendUntil(team, GrsimMove(false, id, 0.0, 0.0, 0.0), ip, port, vision, later(at_place, 6), seconds(30)))
    return std::nullopt;
  const Seen before = *robot();
  const auto frames = static_cast<uint32_t>(std::lround(std::chrono::duration<double>(drive).count() * kCameraHz));
  if (!SendUntil(team, GrsimMove(false, id, 1.0, 0.0, 0.0), ip, port, vision, later(before, frames), seconds(30)))
    return std::nullopt;
  const Seen after = *robot();
  KeepSending(team, GrsimMove(false, id, 0.0, 0.0, 0.0), ip, port, vision, std::chrono::milliseconds(50));
  return (after.x - before.x) / 1000.0;
}

}  // namespace turf::test
