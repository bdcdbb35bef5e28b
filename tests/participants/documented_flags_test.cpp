// Every flag the READMEs document exists: a participant's README names only flags its executable's --help
// lists, and every flag of the main README is one that some turf executable or script offers. A renamed or
// removed flag fails here instead of in a user's terminal.
#include <gtest/gtest.h>
#include <stdio.h>

#include <regex>
#include <set>
#include <string>
#include <vector>

#include "tests/support/source_files.h"

namespace turf::test {
namespace {

// What a command prints (stdout and stderr).
std::string Output(const std::string& command) {
  std::string out;
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (pipe == nullptr) return out;
  char buffer[4096];
  size_t n;
  while ((n = fread(buffer, 1, sizeof(buffer), pipe)) > 0) out.append(buffer, n);
  pclose(pipe);
  return out;
}

std::set<std::string> Flags(const std::string& text) {
  static const std::regex kFlag("--[a-z][a-z0-9-]*[a-z0-9]");
  std::set<std::string> flags;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), kFlag); it != std::sregex_iterator(); ++it)
    flags.insert(it->str());
  return flags;
}

std::string Help(const std::string& executable) {
  return Output(std::string(TURF_BINARY_DIR) + "/participants/" + executable + " --help");
}

const struct {
  const char* readme;      // from the source tree's top
  const char* executable;  // under build/participants/
} kParticipants[] = {
    {"participants/grsim_bridge/README.md", "grsim_bridge/turf-grsim-bridge"},
    {"participants/vision_bridge/README.md", "vision_bridge/turf-vision-bridge"},
    {"participants/simproto_bridge/README.md", "simproto_bridge/turf-simproto-bridge"},
    {"participants/viewer/README.md", "viewer/turf-viewer"},
};

TEST(DocumentedFlags, EachParticipantsReadmeNamesOnlyFlagsItsHelpLists) {
  for (const auto& p : kParticipants) {
    const std::string help = Help(p.executable);
    ASSERT_NE(help.find("--help"), std::string::npos) << p.executable << " --help printed:\n" << help;
    const std::set<std::string> offered = Flags(help);
    const std::set<std::string> documented = Flags(SourceFile(p.readme));
    EXPECT_FALSE(documented.empty()) << p.readme;
    for (const std::string& flag : documented) EXPECT_TRUE(offered.count(flag)) << p.readme << " documents " << flag;
  }
}

TEST(DocumentedFlags, EveryFlagOfTheMainReadmeExists) {
  std::set<std::string> offered;
  for (const char* executable : {"sim/turf-sim", "grsim_bridge/turf-grsim-bridge", "vision_bridge/turf-vision-bridge",
                                 "simproto_bridge/turf-simproto-bridge", "simspark_bridge/turf-simspark-bridge",
                                 "viewer/turf-viewer", "launcher/turf", "launcher/turf launch"}) {
    const std::set<std::string> flags = Flags(Help(executable));
    offered.insert(flags.begin(), flags.end());
  }
  for (const char* script :
       {"scripts/soak-tests.sh", "scripts/run.sh", "scripts/test.sh", "scripts/check-format.sh", "bench/run.sh"}) {
    const std::set<std::string> flags = Flags(SourceFile(script));
    offered.insert(flags.begin(), flags.end());
  }
  const std::set<std::string> documented = Flags(SourceFile("README.md"));
  for (const std::string& flag : documented) EXPECT_TRUE(offered.count(flag)) << "README.md documents " << flag;
}

// The check itself can fail: a flag no executable has is not found.
TEST(DocumentedFlags, AnInventedFlagIsNotOffered) {
  EXPECT_EQ(Flags(Help("grsim_bridge/turf-grsim-bridge")).count("--no-such-flag"), 0u);
  EXPECT_EQ(Flags("use --port 5 and --blue-status-port, not -p"),
            (std::set<std::string>{"--port", "--blue-status-port"}));
}

}  // namespace
}  // namespace turf::test
