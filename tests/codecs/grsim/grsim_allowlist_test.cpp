// turf-grsim-bridge's source allowlists, without sockets: which lists a decoded packet must pass (GatesFor), the
// decision for the worked example of the README (two team machines, the operator on the physics host), and the
// flags with their default (anyone).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "participants/grsim_bridge/grsim_bridge.h"
#include "participants/grsim_bridge/grsim_bridge_flags.h"

namespace turf {
namespace {

grsim::GrsimRequests Commands(idl::Team team) {
  grsim::GrsimRequests r;
  r.command_team = team;
  r.commands.resize(1);
  return r;
}

grsim::GrsimRequests Replacement() {
  grsim::GrsimRequests r;
  r.controls.resize(1);
  return r;
}

// Admitted the way the bridge decides: every gate GatesFor names allows the sender.
bool Admitted(const grsim::GrsimRequests& r, SourceGates& gates, const char* ip) {
  for (const SourceGate* gate : GatesFor(r, gates))
    if (gate != nullptr && !gate->Allows(*MakeEndpoint(ip, 10000))) return false;
  return true;
}

TEST(GrsimAllowlist, APacketNeedsItsTeamsListAndForAReplacementTheOperators) {
  SourceGates gates(SourceAllowlists{});
  EXPECT_EQ(GatesFor(Commands(idl::TEAM_BLUE), gates)[0], &gates.blue);
  EXPECT_EQ(GatesFor(Commands(idl::TEAM_BLUE), gates)[1], nullptr);
  EXPECT_EQ(GatesFor(Commands(idl::TEAM_YELLOW), gates)[0], &gates.yellow);
  EXPECT_EQ(GatesFor(Replacement(), gates)[0], nullptr);
  EXPECT_EQ(GatesFor(Replacement(), gates)[1], &gates.operators);
  grsim::GrsimRequests both = Commands(idl::TEAM_YELLOW);
  both.controls.resize(2);
  EXPECT_EQ(GatesFor(both, gates)[0], &gates.yellow);
  EXPECT_EQ(GatesFor(both, gates)[1], &gates.operators);
  grsim::GrsimRequests empty_team;  // grSim_Commands with no robot command still names a team (its status address)
  empty_team.command_team = idl::TEAM_BLUE;
  EXPECT_EQ(GatesFor(empty_team, gates)[0], &gates.blue);
}

// The README's example: blue on 10.0.0.11, yellow on 10.0.0.12, the operator on the physics host (10.0.0.1).
TEST(GrsimAllowlist, EachTeamMachineCommandsOnlyItsTeamAndOnlyTheOperatorReplaces) {
  SourceGates gates({{"10.0.0.11"}, {"10.0.0.12"}, {"10.0.0.1", "127.0.0.1"}});
  EXPECT_TRUE(Admitted(Commands(idl::TEAM_BLUE), gates, "10.0.0.11"));
  EXPECT_FALSE(Admitted(Commands(idl::TEAM_BLUE), gates, "10.0.0.12"));
  EXPECT_TRUE(Admitted(Commands(idl::TEAM_YELLOW), gates, "10.0.0.12"));
  EXPECT_FALSE(Admitted(Commands(idl::TEAM_YELLOW), gates, "10.0.0.11"));
  EXPECT_FALSE(Admitted(Commands(idl::TEAM_BLUE), gates, "10.0.0.99"));
  EXPECT_FALSE(Admitted(Replacement(), gates, "10.0.0.11"));
  EXPECT_TRUE(Admitted(Replacement(), gates, "10.0.0.1"));
  EXPECT_TRUE(Admitted(Replacement(), gates, "127.0.0.1"));
  grsim::GrsimRequests both = Commands(idl::TEAM_BLUE);  // a team's commands with a replacement: refused whole
  both.controls.resize(1);
  EXPECT_FALSE(Admitted(both, gates, "10.0.0.11"));
  EXPECT_FALSE(Admitted(both, gates, "10.0.0.1"));
}

// Only the lists given are checked: a team's list alone leaves the other team and replacement open.
TEST(GrsimAllowlist, AListNotGivenAdmitsAnyone) {
  SourceGates gates({{"10.0.0.11"}, {}, {}});
  EXPECT_FALSE(Admitted(Commands(idl::TEAM_BLUE), gates, "10.0.0.12"));
  EXPECT_TRUE(Admitted(Commands(idl::TEAM_YELLOW), gates, "203.0.113.7"));
  EXPECT_TRUE(Admitted(Replacement(), gates, "203.0.113.7"));
}

bool Parse(std::vector<std::string> args, GrsimBridgeOptions* o) {
  ParticipantMain participant("turf-grsim-bridge", "test");
  std::vector<int> wheel_order = {4, 3, 2, 1};
  AddGrsimBridgeFlags(participant, *o, wheel_order);
  args.insert(args.begin(), "turf-grsim-bridge");
  std::vector<const char*> argv;
  for (const std::string& a : args) argv.push_back(a.c_str());
  try {
    participant.app().parse(static_cast<int>(argv.size()), argv.data());
    return true;
  } catch (const CLI::ParseError&) {
    return false;
  }
}

TEST(GrsimAllowlist, FlagsDefaultToAnyoneAndRefuseBadEntries) {
  GrsimBridgeOptions o;
  ASSERT_TRUE(Parse({}, &o));
  EXPECT_TRUE(o.allow.blue.empty());
  EXPECT_TRUE(o.allow.yellow.empty());
  EXPECT_TRUE(o.allow.operators.empty());
  ASSERT_TRUE(Parse({"--blue-allow", "10.0.0.11", "--yellow-allow", "10.0.0.12", "--yellow-allow", "10.0.1.0/24",
                     "--operator-allow", "127.0.0.1"},
                    &o));
  EXPECT_EQ(o.allow.blue, (std::vector<std::string>{"10.0.0.11"}));
  EXPECT_EQ(o.allow.yellow, (std::vector<std::string>{"10.0.0.12", "10.0.1.0/24"}));
  EXPECT_EQ(o.allow.operators, (std::vector<std::string>{"127.0.0.1"}));
  GrsimBridgeOptions bad;
  EXPECT_FALSE(Parse({"--blue-allow", "blue.example"}, &bad));
  EXPECT_FALSE(Parse({"--operator-allow", "::1"}, &bad));
  // Comma-separated as well (a launch profile's list, or --set's value, comes so): each entry checked.
  GrsimBridgeOptions listed;
  ASSERT_TRUE(Parse({"--blue-allow", "10.0.0.11,10.0.1.0/24"}, &listed));
  EXPECT_EQ(listed.allow.blue, (std::vector<std::string>{"10.0.0.11", "10.0.1.0/24"}));
  EXPECT_FALSE(Parse({"--blue-allow", "10.0.0.11,blue.example"}, &bad));
}

}  // namespace
}  // namespace turf
