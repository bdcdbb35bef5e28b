// turf-simproto-bridge's source allowlists, without traffic: the flags of both homes (turf-simproto-bridge and
// turf-sim --simproto, simproto_flags.h) with their default (anyone), and a bad entry refused at construction.
// Which list guards which port, over real UDP: bridge_test.cpp (ASenderNotOnThePortsAllowlistMovesNothing).
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "dds/memory_bus.h"
#include "participants/simproto_bridge/simproto_bridge.h"
#include "participants/simproto_bridge/simproto_flags.h"
#include "tests/support/cli_parse.h"

namespace turf {
namespace {

bool Parse(const std::string& prefix, std::vector<std::string> args, SimprotoBridgeOptions* o) {
  CLI::App app;
  AddSimprotoAllowFlags(app, *o, prefix);
  return test::ParseArgs(app, std::move(args));
}

TEST(SimprotoAllowlist, BothHomesHaveTheFlagsAndTheirDefaultIsAnyone) {
  for (const std::string prefix : {"", "simproto-"}) {
    SimprotoBridgeOptions o;
    ASSERT_TRUE(Parse(prefix, {}, &o)) << prefix;
    EXPECT_TRUE(o.allow.blue.empty() && o.allow.yellow.empty() && o.allow.operators.empty()) << prefix;
    const std::string flag = "--" + prefix;
    ASSERT_TRUE(Parse(prefix,
                      {flag + "blue-allow", "10.0.0.11", flag + "yellow-allow", "10.0.0.12", flag + "operator-allow",
                       "10.0.0.1", flag + "operator-allow", "127.0.0.0/8"},
                      &o))
        << prefix;
    EXPECT_EQ(o.allow.blue, (std::vector<std::string>{"10.0.0.11"}));
    EXPECT_EQ(o.allow.yellow, (std::vector<std::string>{"10.0.0.12"}));
    EXPECT_EQ(o.allow.operators, (std::vector<std::string>{"10.0.0.1", "127.0.0.0/8"}));
    SimprotoBridgeOptions bad;
    EXPECT_FALSE(Parse(prefix, {flag + "blue-allow", "team.example"}, &bad)) << prefix;
    EXPECT_FALSE(Parse(prefix, {flag + "operator-allow", "::1"}, &bad)) << prefix;  // the ports are IPv4
    EXPECT_FALSE(Parse(prefix, {flag + "yellow-allow", "10.0.0.0/40"}, &bad)) << prefix;
  }
}

// Options filled in code (turf-sim's host, tests) are checked too: a bad entry stops the bridge before it binds.
TEST(SimprotoAllowlist, ABadEntryInTheOptionsIsRefusedAtConstruction) {
  dds::MemoryBus bus;
  SimprotoBridgeOptions o;
  o.control_port = o.blue_port = o.yellow_port = o.sync_port = 0;  // no sockets
  o.allow.operators = {"127.0.0.1", "operator.example"};
  try {
    SimprotoBridge bridge(o, bus);
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("operator.example"), std::string::npos) << e.what();
  }
  o.allow.operators = {"127.0.0.1"};
  EXPECT_NO_THROW({ const SimprotoBridge bridge(o, bus); });
}

}  // namespace
}  // namespace turf
