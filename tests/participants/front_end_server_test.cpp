// The 3D-league front-ends' TCP side (participants/common/front_end_server.h): what max_clients counts.
#include "participants/common/front_end_server.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <functional>
#include <memory>
#include <vector>

#include "tests/support/tcp_connect.h"

namespace turf {
namespace {

// A server on a free loopback port admitting at most three clients; `admit` runs for each new one.
struct ThreeClients {
  explicit ThreeClients(std::function<void(FrontEndServer&, FrontEndClient&)> admit) : rejects("test input") {
    FrontEndServer::Hooks hooks;
    hooks.admit = [this, admit](FrontEndClient& c, const std::string&, std::string*) {
      admit(*server, c);
      c.agent = admitted++;
      return true;
    };
    hooks.message = [](FrontEndClient&, const std::string&) {};
    hooks.left = [](const FrontEndClient&) {};
    FrontEndServer::Options options;
    options.listen = "127.0.0.1";
    options.monitor = false;
    options.max_clients = 3;
    server = std::make_unique<FrontEndServer>(options, "test client", &rejects, hooks);
  }
  // `n` clients connect before the server polls; then it polls until each is admitted or refused.
  std::vector<int> Burst(int n) {
    std::vector<int> fds;
    for (int i = 0; i < n; ++i) fds.push_back(test::ConnectLoopback(server->agent_port()));
    for (int polls = 0; polls < 100 && admitted + static_cast<int>(rejects.Count("too_many_clients")) < n; ++polls)
      server->Poll(std::chrono::milliseconds(100));
    return fds;
  }

  RejectLog rejects;
  std::unique_ptr<FrontEndServer> server;
  int admitted = 0;
};

// A client replaced by the next one (HLVS: a robot's reconnecting client) is only marked to be dropped until the poll
// ends; max_clients counted it, so a burst of reconnects on one port refused other ports' clients (32 "connected" on a
// bridge of 2 robots).
TEST(FrontEndServer, ClientsMarkedToBeDroppedDoNotCountAgainstMaxClients) {
  ThreeClients s([](FrontEndServer& server, FrontEndClient&) {
    for (const auto& [fd, other] : server.clients()) server.MarkDrop(fd, "replaced");  // each replaces the last
  });
  const std::vector<int> fds = s.Burst(8);
  for (int fd : fds) EXPECT_GE(fd, 0);
  EXPECT_EQ(s.admitted, 8);
  EXPECT_EQ(s.rejects.Count("too_many_clients"), 0u);
  EXPECT_EQ(s.server->clients().size(), 1u) << "the replaced ones are gone after the poll";
  for (int fd : fds) close(fd);
}

TEST(FrontEndServer, MaxClientsBoundsClientsThatStay) {
  ThreeClients s([](FrontEndServer&, FrontEndClient&) {});
  const std::vector<int> fds = s.Burst(5);
  EXPECT_EQ(s.admitted, 3);
  EXPECT_EQ(s.rejects.Count("too_many_clients"), 2u);
  for (int fd : fds) close(fd);
}

}  // namespace
}  // namespace turf
