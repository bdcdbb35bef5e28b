// The SimSpark bridge's operator allowlist: its default (this machine) and the flag turf-simspark-bridge and
// turf-sim --simspark share (simspark_flags.h). The list itself: tests/participants/address_allowlist_test.cpp.
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "participants/common/address_allowlist.h"
#include "participants/simspark_bridge/simspark_flags.h"
#include "tests/support/cli_parse.h"

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

// The flag turf-simspark-bridge and turf-sim --simspark share (simspark_flags.h).
TEST(OperatorAllowFlag, GivenItReplacesTheDefaultAndBadEntriesAreRefused) {
  const auto parse = [](std::vector<std::string> args, SimSparkBridgeOptions* o) {
    CLI::App app;
    AddSimSparkOperatorFlag(app, *o, "simspark-");
    return test::ParseArgs(app, std::move(args));
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
