// The TCP side shared by the front-ends (SimSpark, RCSSServerMJ and HLVS bridges): an agent port (more for HLVS: one
// per robot) and a monitor port (none for HLVS), length-prefixed frames (codecs/simspark/framing.h), and the
// untrusted-client rules: at most max_clients, a frame above the payload limit or a client that stops reading
// (max_unsent) drops that client only. Clients connecting and leaving are logged at most once a second per kind. What a
// client means (agents, monitors, the session) is the owner's, through the hooks.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "codecs/simspark/framing.h"
#include "core/pinned.h"
#include "participants/common/process.h"
#include "participants/common/tcp.h"

namespace turf {

struct FrontEndClient {
  std::unique_ptr<TcpPeer> peer;
  simspark::FrameDecoder decoder;
  bool monitor = false;
  int agent = -1;     // the owner's session id (agents only)
  int role = 0;       // the owner's (monitors only)
  uint16_t port = 0;  // the local port it came in on
};

class FrontEndServer : Pinned {
 public:
  struct Hooks {
    // A new client (within max_clients), not yet served: sets its agent or role and logs it on connections();
    // false: refused (closed). A non-empty *greeting is sent to it once it is served.
    std::function<bool(FrontEndClient& client, const std::string& address, std::string* greeting)> admit;
    std::function<void(FrontEndClient& client, const std::string& payload)> message;
    // A client is dropped (after its line on connections()).
    std::function<void(const FrontEndClient& client)> left;
  };
  struct Options {
    std::string listen;
    uint16_t agent_port = 0;
    uint16_t monitor_port = 0;
    size_t max_clients = 64;
    size_t max_unsent = 1 << 20;
    std::vector<uint16_t> more_agent_ports;  // bound after agent_port, same rules (0: any free port)
    bool monitor = true;                     // false: no monitor port (monitor_port ignored)
  };
  // Binds every port; throws std::runtime_error if it cannot. `rejects` (refused input) outlives the server.
  FrontEndServer(const Options& options, const std::string& connection_log, RejectLog* rejects, Hooks hooks);

  uint16_t agent_port() const { return listeners_.front().socket.LocalPort(); }
  uint16_t monitor_port() const;              // 0 without one
  std::vector<uint16_t> agent_ports() const;  // as bound: agent_port, then more_agent_ports
  RejectLog& connections() { return connections_; }
  std::map<int, FrontEndClient>& clients() { return clients_; }

  // Accepts, writes what is waiting and reads (hooks.message per frame) for up to `timeout`; then drops. False when
  // nothing happened within the timeout.
  bool Poll(std::chrono::milliseconds timeout);
  void Send(int fd, const std::string& framed);
  void SendToAgent(int agent, const std::string& framed);
  void DropAgent(int agent, const std::string& why);
  void MarkDrop(int fd, const std::string& why) { drops_.emplace_back(fd, why); }
  void FlushDrops();

 private:
  struct Listener {
    TcpListener socket;
    bool monitor = false;
  };
  void AcceptAll(Listener* listener);
  size_t LiveClients() const;  // clients not marked to be dropped: what max_clients bounds
  void ReadClient(int fd);

  Options options_;
  RejectLog* rejects_;
  Hooks hooks_;
  RejectLog connections_;            // clients connecting and leaving (LogLine::kEvent)
  std::vector<Listener> listeners_;  // agent ports in order, then the monitor port
  std::map<int, FrontEndClient> clients_;
  std::vector<std::pair<int, std::string>> drops_;
};

}  // namespace turf
