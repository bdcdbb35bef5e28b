// The SimSpark bridge's operator allowlist (participants/simspark_bridge/operator_allowlist.h): which monitor-port
// peers may end, restart or rewrite the match.
#include "participants/simspark_bridge/operator_allowlist.h"

#include <gtest/gtest.h>

#include "participants/simspark_bridge/simspark_flags.h"

#include <stdexcept>
#include <string>

namespace turf {
namespace {

TEST(OperatorAllowlist, TheDefaultIsThisMachineOnly) {
  const AddressAllowlist list(kDefaultOperatorAllow);
  for (const char* peer : {"127.0.0.1:4000", "127.255.0.9:1", "127.0.0.1", "[::1]:3200", "::1"})
    EXPECT_TRUE(list.Allows(peer)) << peer;
  for (const char* peer : {"10.0.0.1:4000", "192.168.1.2:3200", "128.0.0.1:1", "0.0.0.0:1", "[::2]:3200",
                           "[::ffff:127.0.0.1]:1", "", "localhost:3200", "127.0.0.1.5:1"})
    EXPECT_FALSE(list.Allows(peer)) << peer;
}

TEST(OperatorAllowlist, RangesMatchTheirPrefixBits) {
  const AddressAllowlist list({"10.1.2.3/8", "192.168.7.0/23", "203.0.113.5", "2001:db8::/32"});
  EXPECT_TRUE(list.Allows("10.200.0.1:1"));  // bits past the prefix are ignored
  EXPECT_TRUE(list.Allows("192.168.6.1:1"));
  EXPECT_TRUE(list.Allows("192.168.7.255:1"));
  EXPECT_FALSE(list.Allows("192.168.8.0:1"));
  EXPECT_TRUE(list.Allows("203.0.113.5:9"));
  EXPECT_FALSE(list.Allows("203.0.113.6:9"));
  EXPECT_FALSE(list.Allows("127.0.0.1:9"));  // given, the list replaces the default
  EXPECT_TRUE(list.Allows("[2001:db8:1::7]:3200"));
  EXPECT_FALSE(list.Allows("[2001:db9::7]:3200"));
  EXPECT_TRUE(AddressAllowlist({"0.0.0.0/0"}).Allows("8.8.8.8:53"));  // everybody, if one insists
  EXPECT_FALSE(AddressAllowlist({}).Allows("127.0.0.1:1"));           // nobody
}

TEST(OperatorAllowlist, BadEntriesAreNamed) {
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

// The flag turf-simspark-bridge and turf-sim --simspark share (simspark_flags.h).
TEST(OperatorAllowFlag, GivenItReplacesTheDefaultAndBadEntriesAreRefused) {
  const auto parse = [](std::vector<std::string> args, SimSparkBridgeOptions* o) {
    CLI::App app;
    AddSimSparkOperatorFlag(app, *o, "simspark-");
    args.insert(args.begin(), "turf-sim");
    std::vector<const char*> argv;
    for (const std::string& a : args) argv.push_back(a.c_str());
    try {
      app.parse(static_cast<int>(argv.size()), argv.data());
      return true;
    } catch (const CLI::ParseError&) {
      return false;
    }
  };
  SimSparkBridgeOptions o;
  ASSERT_TRUE(parse({}, &o));
  EXPECT_EQ(o.operator_allow, kDefaultOperatorAllow);
  ASSERT_TRUE(parse({"--simspark-operator-allow", "10.0.0.0/8", "--simspark-operator-allow", "::1"}, &o));
  EXPECT_EQ(o.operator_allow, (std::vector<std::string>{"10.0.0.0/8", "::1"}));
  SimSparkBridgeOptions bad;
  EXPECT_FALSE(parse({"--simspark-operator-allow", "10.0.0.0/33"}, &bad));
  EXPECT_FALSE(parse({"--simspark-operator-allow", "operator.example"}, &bad));
}

}  // namespace
}  // namespace turf
