// The 3D-league front-ends' TCP side (participants/common/front_end_server.h): what max_clients counts.
#include "participants/common/front_end_server.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <vector>

#include "tests/support/tcp_connect.h"

namespace turf {
namespace {

// A client replaced by the next one (HLVS: a robot's reconnecting client) is only marked to be dropped until the poll
// ends; max_clients counted it, so a burst of reconnects on one port refused other ports' clients (32 "connected" on a
// bridge of 2 robots).
TEST(FrontEndServer, ClientsMarkedToBeDroppedDoNotCountAgainstMaxClients) {
  RejectLog rejects("test input");
  FrontEndServer* server = nullptr;
  int admitted = 0;
  FrontEndServer::Hooks hooks;
  hooks.admit = [&](FrontEndClient& c, const std::string&, std::string*) {
    for (const auto& [fd, other] : server->clients()) server->MarkDrop(fd, "replaced");  // each replaces the last
    c.agent = admitted++;
    return true;
  };
  hooks.message = [](FrontEndClient&, const std::string&) {};
  hooks.left = [](const FrontEndClient&) {};
  FrontEndServer::Options options;
  options.listen = "127.0.0.1";
  options.monitor = false;
  options.max_clients = 3;
  FrontEndServer s(options, "test client", &rejects, hooks);
  server = &s;

  constexpr int kBurst = 8;  // all waiting to be accepted in one poll
  std::vector<int> fds;
  for (int i = 0; i < kBurst; ++i) {
    fds.push_back(test::ConnectLoopback(s.agent_port()));
    ASSERT_GE(fds.back(), 0);
  }
  for (int polls = 0; polls < 100 && admitted < kBurst; ++polls) s.Poll(std::chrono::milliseconds(100));
  EXPECT_EQ(admitted, kBurst);
  EXPECT_EQ(rejects.Count("too_many_clients"), 0u);
  EXPECT_EQ(s.clients().size(), 1u) << "the replaced ones are gone after the poll";
  for (int fd : fds) close(fd);
}

TEST(FrontEndServer, MaxClientsBoundsClientsThatStay) {
  RejectLog rejects("test input");
  int admitted = 0;
  FrontEndServer::Hooks hooks;
  hooks.admit = [&](FrontEndClient& c, const std::string&, std::string*) {
    c.agent = admitted++;
    return true;
  };
  hooks.message = [](FrontEndClient&, const std::string&) {};
  hooks.left = [](const FrontEndClient&) {};
  FrontEndServer::Options options;
  options.listen = "127.0.0.1";
  options.monitor = false;
  options.max_clients = 3;
  FrontEndServer s(options, "test client", &rejects, hooks);
  std::vector<int> fds;
  for (int i = 0; i < 5; ++i) {
    fds.push_back(test::ConnectLoopback(s.agent_port()));
    ASSERT_GE(fds.back(), 0);
  }
  for (int polls = 0; polls < 100 && admitted + rejects.Count("too_many_clients") < 5; ++polls)
    s.Poll(std::chrono::milliseconds(100));
  EXPECT_EQ(admitted, 3);
  EXPECT_EQ(rejects.Count("too_many_clients"), 2u);
  for (int fd : fds) close(fd);
}

}  // namespace
}  // namespace turf
