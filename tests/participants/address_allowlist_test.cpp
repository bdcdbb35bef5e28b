// Source-address allowlists (participants/common/address_allowlist.h) and the SSL bridges' gates over them
// (source_gate.h): which addresses a list allows, the default of the UDP lists (anyone), how a refusal is counted,
// and the flag check that names a bad entry. Pure: no sockets.
#include "participants/common/address_allowlist.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "participants/common/cli_checks.h"
#include "participants/common/source_gate.h"
#include "tests/support/cli_parse.h"

namespace turf {
namespace {

UdpEndpoint From(const char* ip) { return *MakeEndpoint(ip, 40000); }

TEST(AddressAllowlist, RangesMatchTheirPrefixBits) {
  const AddressAllowlist list({"10.1.2.3/8", "192.168.7.0/23", "203.0.113.5", "2001:db8::/32"});
  EXPECT_TRUE(list.Allows("10.200.0.1:1"));  // bits past the prefix are ignored
  EXPECT_TRUE(list.Allows("192.168.6.1:1"));
  EXPECT_TRUE(list.Allows("192.168.7.255:1"));
  EXPECT_FALSE(list.Allows("192.168.8.0:1"));
  EXPECT_TRUE(list.Allows("203.0.113.5:9"));
  EXPECT_FALSE(list.Allows("203.0.113.6:9"));
  EXPECT_FALSE(list.Allows("127.0.0.1:9"));
  EXPECT_TRUE(list.Allows("[2001:db8:1::7]:3200"));
  EXPECT_FALSE(list.Allows("[2001:db9::7]:3200"));
  EXPECT_TRUE(AddressAllowlist({"0.0.0.0/0"}).Allows("8.8.8.8:53"));  // everybody, if one insists
  EXPECT_FALSE(AddressAllowlist({}).Allows("127.0.0.1:1"));           // nobody
}

// The UDP bridges ask with the datagram's IPv4 address, no text: the same answers as the text form.
TEST(AddressAllowlist, Ipv4InHostOrderAnswersAsItsText) {
  const AddressAllowlist list({"10.1.2.3/8", "192.168.7.0/23", "203.0.113.5", "::/0"});
  for (const char* ip : {"10.200.0.1", "192.168.6.1", "192.168.7.255", "192.168.8.0", "203.0.113.5", "203.0.113.6",
                         "127.0.0.1", "0.0.0.0", "255.255.255.255"})
    EXPECT_EQ(list.AllowsIpv4(From(ip).ip()), list.Allows(ip)) << ip;
  EXPECT_FALSE(list.AllowsIpv4(From("127.0.0.1").ip()));  // an IPv6 range never holds an IPv4 address
  EXPECT_TRUE(AddressAllowlist({"0.0.0.0/0"}).AllowsIpv4(From("8.8.8.8").ip()));
}

TEST(AddressAllowlist, BadEntriesAreNamed) {
  for (const char* bad : {"localhost", "10.0.0.0/33", "::1/129", "10.0.0.0/", "10.0.0.0/-1", "10.0.0.0/8x", "10.0.0/8",
                          "", "1.2.3.4:80"}) {
    std::string error;
    EXPECT_FALSE(ParseAddressRange(bad, &error).has_value()) << bad;
    EXPECT_NE(error.find(bad), std::string::npos) << error;
  }
  EXPECT_THROW(AddressAllowlist({"127.0.0.1", "nonsense"}), std::invalid_argument);
  std::string error;
  const std::optional<AddressRange> v6 = ParseAddressRange("fe80::/10", &error);
  ASSERT_TRUE(v6.has_value()) << error;
  EXPECT_TRUE(v6->v6);
  EXPECT_EQ(v6->prefix, 10);
}

// No entries: anyone, as before the lists existed; nothing is counted.
TEST(SourceGate, WithoutEntriesEveryoneIsAdmitted) {
  SourceGates gates(SourceAllowlists{});
  RejectLog log("test datagram");
  for (SourceGate* gate : {&gates.blue, &gates.yellow, &gates.operators}) {
    EXPECT_EQ(gate->Describe(), "anyone");
    for (const char* ip : {"127.0.0.1", "10.0.0.11", "203.0.113.9"})
      EXPECT_TRUE(gate->Admit(From(ip), log, gate->name() + ".not_allowed")) << gate->name() << " " << ip;
  }
  EXPECT_EQ(gates.refused(), 0u);
  EXPECT_EQ(log.Total(), 0u);
}

// Each list guards its own: a refusal is counted by the gate that refused and by the bridge's log, under its kind.
TEST(SourceGate, ARefusedSourceIsCountedUnderItsKind) {
  SourceGates gates({{"10.0.0.11"}, {"10.0.0.12"}, {"10.0.0.1/32", "192.168.0.0/16"}});
  RejectLog log("test datagram");
  EXPECT_TRUE(gates.team(0).Admit(From("10.0.0.11"), log, "blue.not_allowed"));
  EXPECT_FALSE(gates.team(0).Admit(From("10.0.0.12"), log, "blue.not_allowed"));  // yellow's machine
  EXPECT_TRUE(gates.team(1).Admit(From("10.0.0.12"), log, "yellow.not_allowed"));
  EXPECT_FALSE(gates.team(1).Admit(From("10.0.0.11"), log, "yellow.not_allowed"));
  EXPECT_FALSE(gates.team(1).Admit(From("10.0.0.13"), log, "yellow.not_allowed"));
  EXPECT_TRUE(gates.operators.Admit(From("192.168.3.4"), log, "control.not_allowed"));
  EXPECT_FALSE(gates.operators.Admit(From("10.0.0.11"), log, "control.not_allowed"));
  EXPECT_EQ(gates.blue.refused(), 1u);
  EXPECT_EQ(gates.yellow.refused(), 2u);
  EXPECT_EQ(gates.operators.refused(), 1u);
  EXPECT_EQ(gates.refused(), 4u);
  EXPECT_EQ(log.Count("blue.not_allowed"), 1u);
  EXPECT_EQ(log.Count("yellow.not_allowed"), 2u);
  EXPECT_EQ(log.Count("control.not_allowed"), 1u);
  EXPECT_EQ(gates.operators.Describe(), "10.0.0.1/32, 192.168.0.0/16");
}

TEST(SourceGate, ABadEntryNamesItsList) {
  try {
    SourceGates gates({{}, {"10.0.0.12", "yellow.example"}, {}});
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("yellow"), std::string::npos) << what;
    EXPECT_NE(what.find("yellow.example"), std::string::npos) << what;
  }
}

// The UDP bridges' flag (cli_checks.h): repeatable, empty unless given, IPv4 only (the ports listen on IPv4).
TEST(AllowFlag, RepeatableIpv4AndBadEntriesAreRefused) {
  const auto parse = [](std::vector<std::string> args, std::vector<std::string>* entries) {
    CLI::App app;
    AddAllowOption(app, "--blue-allow", *entries, "blue");
    return test::ParseArgs(app, std::move(args));
  };
  std::vector<std::string> entries;
  ASSERT_TRUE(parse({}, &entries));
  EXPECT_TRUE(entries.empty());
  ASSERT_TRUE(parse({"--blue-allow", "10.0.0.11", "--blue-allow", "192.168.0.0/16"}, &entries));
  EXPECT_EQ(entries, (std::vector<std::string>{"10.0.0.11", "192.168.0.0/16"}));
  for (const char* bad : {"::1", "2001:db8::/32", "10.0.0.0/33", "team.example", ""}) {
    std::vector<std::string> refused;
    EXPECT_FALSE(parse({"--blue-allow", bad}, &refused)) << bad;
  }
}

}  // namespace
}  // namespace turf
