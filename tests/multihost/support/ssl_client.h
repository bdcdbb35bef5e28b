// What an SSL team's software does, for the multi-host, fault and launch
// tests: sends grSim packets and decodes the SSL-Vision stream (turf's protos,
// codecs/proto), over plain UDP sockets on an address
// of the caller's choice (127.0.0.1: unicast within one host).
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <utility>

#include "tests/support/team_packets.h"

namespace turf::test {

using SteadyClock = std::chrono::steady_clock;

// A UDP socket bound to ip:port (port 0: any), made in the calling thread's
// network namespace; receives with a 20 ms timeout.
class UdpSocket {
 public:
  explicit UdpSocket(const std::string& ip = "127.0.0.1", int port = 0);
  ~UdpSocket();
  UdpSocket(const UdpSocket&) = delete;
  UdpSocket& operator=(const UdpSocket&) = delete;
  bool ok() const { return fd_ >= 0; }
  void Send(const std::string& bytes, const std::string& ip, int port);
  std::optional<std::string> Receive();

 private:
  int fd_ = -1;
};

struct Seen {
  double x = 0, y = 0, t = 0;  // mm, mm, t_capture
  uint32_t frame = 0;          // frame_number: turf-sim counts captures, 60 a second of simulation time
};

// The SSL-Vision stream as a team decodes it.
class VisionClient {
 public:
  explicit VisionClient(const std::string& ip, int port) : socket_(ip, port) {}
  bool ok() const { return socket_.ok(); }
  // Reads everything that arrives for `duration`.
  void Drain(std::chrono::milliseconds duration);
  // Reads until a detection arrives; the time it took, or nullopt after `timeout`.
  std::optional<std::chrono::milliseconds> UntilDetection(std::chrono::milliseconds timeout);
  // Reads until every one of `cameras` cameras and geometry were seen.
  bool WaitForStream(size_t cameras, std::chrono::milliseconds timeout);
  std::optional<Seen> Robot(bool yellow, uint32_t id) const;

  int detections = 0;
  bool geometry = false;
  std::map<uint32_t, uint32_t> cameras;  // camera id -> last frame number
  // The longest run of a camera's frames that never arrived (frame numbers skipped between two that did), any
  // camera, since the last ResetGaps().
  uint32_t longest_gap = 0;
  void ResetGaps() { longest_gap = 0; }
  std::optional<SteadyClock::time_point> last_detection;

 private:
  bool ReadOne();  // false if nothing arrived within the socket timeout
  UdpSocket socket_;
  std::map<std::pair<bool, uint32_t>, Seen> robots_;
};

// Sends `packet` at ~60 Hz to ip:port for `duration` while draining vision.
void KeepSending(UdpSocket& team, const std::string& packet, const std::string& ip, int port, VisionClient& vision,
                 std::chrono::milliseconds duration);

// Sends `packet` at ~60 Hz while draining vision, until `done` holds (true) or
// `timeout` passes (false).
bool SendUntil(UdpSocket& team, const std::string& packet, const std::string& ip, int port, VisionClient& vision,
               const std::function<bool()>& done, std::chrono::milliseconds timeout);

// Places robot `id` of blue at (x, y) facing +x (until the vision stream shows
// it there), drives it forward at 1 m/s for `drive` of simulation time (camera
// frames) and returns how far it moved in x (m) in the vision stream; nullopt
// if it was never seen there or the stream stalled (each wait at most 10 s).
std::optional<double> DriveBlueRobot(UdpSocket& team, const std::string& ip, int port, VisionClient& vision, int id,
                                     double x, double y, std::chrono::milliseconds drive);

}  // namespace turf::test
