// Every flag the READMEs document exists: a participant's README names only flags its executable's --help
// lists, and every flag of the main README is one that some turf executable or script offers. A renamed or
// removed flag fails here instead of in a user's terminal.
#include <gtest/gtest.h>

#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "participants/launcher/preflight.h"
#include "tests/support/source_files.h"

namespace turf::test {
namespace {

using launch::LongFlags;

// The flags `participants/<executable> --help` lists (for "launcher/turf launch": the launch subcommand's; for
// "launcher/turf security init": that one's).
std::set<std::string> Help(const std::string& executable) {
  std::vector<std::string> argv;
  std::string word;
  std::istringstream words(executable);
  while (words >> word) argv.push_back(argv.empty() ? std::string(TURF_BINARY_DIR) + "/participants/" + word : word);
  return launch::HelpFlags(argv).value_or(std::set<std::string>{});
}

const struct {
  const char* readme;      // from the source tree's top
  const char* executable;  // under build/participants/
  const char* also = "";   // another executable whose flags the README documents too
} kParticipants[] = {
    {"participants/grsim_bridge/README.md", "grsim_bridge/turf-grsim-bridge"},
    {"participants/vision_bridge/README.md", "vision_bridge/turf-vision-bridge"},
    // Also served in turf-sim's process: turf-sim --simproto ...
    {"participants/simproto_bridge/README.md", "simproto_bridge/turf-simproto-bridge", "sim/turf-sim"},
    {"participants/viewer/README.md", "viewer/turf-viewer"},
    // Also served in turf-sim's process: turf-sim --rcssservermj ...
    {"participants/rcssservermj_bridge/README.md", "rcssservermj_bridge/turf-rcssservermj-bridge", "sim/turf-sim"},
    {"participants/hlvs_bridge/README.md", "hlvs_bridge/turf-hlvs-bridge"},
    {"participants/render/README.md", "render/turf-render"},
};

TEST(DocumentedFlags, EachParticipantsReadmeNamesOnlyFlagsItsHelpLists) {
  for (const auto& p : kParticipants) {
    std::set<std::string> offered = Help(p.executable);
    ASSERT_TRUE(offered.count("--help")) << p.executable << " --help printed no flags";
    if (*p.also != '\0') {
      const std::set<std::string> also = Help(p.also);
      offered.insert(also.begin(), also.end());
    }
    const std::set<std::string> documented = LongFlags(SourceFile(p.readme));
    EXPECT_FALSE(documented.empty()) << p.readme;
    for (const std::string& flag : documented) EXPECT_TRUE(offered.count(flag)) << p.readme << " documents " << flag;
  }
}

TEST(DocumentedFlags, EveryFlagOfTheMainReadmeAndDocsExists) {
  std::set<std::string> offered;
  for (const char* executable :
       {"sim/turf-sim", "grsim_bridge/turf-grsim-bridge", "vision_bridge/turf-vision-bridge",
        "simproto_bridge/turf-simproto-bridge", "simspark_bridge/turf-simspark-bridge",
        "rcssservermj_bridge/turf-rcssservermj-bridge", "hlvs_bridge/turf-hlvs-bridge", "viewer/turf-viewer",
        "launcher/turf", "launcher/turf launch", "launcher/turf security init", "launcher/turf log info",
        "launcher/turf log diff", "recorder/turf-record", "replay/turf-replay", "render/turf-render"}) {
    const std::set<std::string> flags = Help(executable);
    offered.insert(flags.begin(), flags.end());
  }
  for (const char* script : {"scripts/soak-tests.sh", "scripts/run.sh", "scripts/test.sh", "scripts/check-format.sh",
                             "bench/run.sh", "bench/ut_agents/run_match.sh", "bench/ut_agents/replay.py",
                             "bench/ut_agents/compare_replay.py", "bench/rcssservermj_nn/run.sh"}) {
    const std::set<std::string> flags = LongFlags(SourceFile(script));
    offered.insert(flags.begin(), flags.end());
  }
  // The README and the records it points to (docs/).
  for (const char* doc : {"README.md", "docs/performance.md", "docs/fidelity-nao.md"}) {
    const std::set<std::string> documented = LongFlags(SourceFile(doc));
    EXPECT_FALSE(documented.empty()) << doc;
    for (const std::string& flag : documented) EXPECT_TRUE(offered.count(flag)) << doc << " documents " << flag;
  }
}

// The check itself can fail: a flag no executable has is not found.
TEST(DocumentedFlags, AnInventedFlagIsNotOffered) {
  EXPECT_EQ(Help("grsim_bridge/turf-grsim-bridge").count("--no-such-flag"), 0u);
  EXPECT_EQ(LongFlags("use --port 5 and --blue-status-port, not -p"),
            (std::set<std::string>{"--port", "--blue-status-port"}));
}

}  // namespace
}  // namespace turf::test
