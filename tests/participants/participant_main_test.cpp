// The skeleton every participant's main() runs in: the common flags land in
// ParticipantOptions, a refused flag or a bad configuration exits 2 without
// running the body, an exception in the body exits 1, a clean run exits 0.
#include "participants/common/participant_main.h"

#include <gtest/gtest.h>
#include <spdlog/sinks/ringbuffer_sink.h>
#include <spdlog/spdlog.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace turf {
namespace {

// Runs a fresh skeleton with `args` after the program name; `body_runs`
// counts the calls of `body`.
class ParticipantMainTest : public ::testing::Test {
 protected:
  void SetUp() override {
    log_ = std::make_shared<spdlog::sinks::ringbuffer_sink_mt>(64);
    spdlog::default_logger()->sinks().push_back(log_);
  }
  void TearDown() override {
    auto& sinks = spdlog::default_logger()->sinks();
    sinks.erase(std::remove(sinks.begin(), sinks.end(), log_), sinks.end());
  }

  int Run(const std::vector<std::string>& args, const std::function<int()>& body) {
    std::vector<const char*> argv = {"turf-test"};
    for (const std::string& a : args) argv.push_back(a.c_str());
    return participant_.Run(static_cast<int>(argv.size()), argv.data(), [&] {
      ++body_runs_;
      return body();
    });
  }

  bool Logged(const std::string& text) const {
    for (const std::string& line : log_->last_formatted())
      if (line.find(text) != std::string::npos) return true;
    return false;
  }

  ParticipantMain participant_{"turf-test", "turf-test: the skeleton under test"};
  ParticipantOptions options_;
  int body_runs_ = 0;
  std::shared_ptr<spdlog::sinks::ringbuffer_sink_mt> log_;
};

int Clean() { return kExitClean; }

TEST_F(ParticipantMainTest, CommonFlagsAreParsedIntoParticipantOptions) {
  participant_.AddCommonFlags(options_);
  ParticipantOptions seen;
  EXPECT_EQ(Run({"-d", "42", "--prefix", "field2", "--qos", TURF_SOURCE_DIR "/configs/qos/turf_qos.xml", "--log-level",
                 "warn"},
                [&] {
                  seen = options_;
                  return kExitClean;
                }),
            kExitClean);
  EXPECT_EQ(body_runs_, 1);
  EXPECT_EQ(seen.domain, 42);
  EXPECT_EQ(seen.prefix, "field2");
  EXPECT_EQ(seen.qos_file, TURF_SOURCE_DIR "/configs/qos/turf_qos.xml");
  EXPECT_EQ(seen.name, "turf");  // no flag sets the name
  EXPECT_EQ(spdlog::get_level(), spdlog::level::warn);

  ParticipantMain other("turf-test", "another");
  ParticipantOptions long_names;
  other.AddCommonFlags(long_names);
  const char* argv[] = {"turf-test", "--domain", "232", "-p", "x", "--log-level", "info"};
  EXPECT_EQ(other.Run(7, argv, Clean), kExitClean);
  EXPECT_EQ(long_names.domain, 232);
  EXPECT_EQ(long_names.prefix, "x");
}

// A port past 65535 (or 0 where no free port is meant) is a configuration error that names the range.
TEST_F(ParticipantMainTest, PortsAreCheckedAgainstTheirRange) {
  uint16_t port = 20011;
  uint16_t any = 8080;
  participant_.AddPort("--port", port, "a port");
  participant_.AddPort("--any-port", any, "0: any free port", /*zero_allowed=*/true);
  EXPECT_EQ(Run({"--port", "10006", "--any-port", "0"}, Clean), kExitClean);
  EXPECT_EQ(port, 10006);
  EXPECT_EQ(any, 0);
  for (const std::vector<std::string>& args :
       std::vector<std::vector<std::string>>{{"--port", "99999"}, {"--port", "0"}, {"--port", "-1"}, {"--port", "x"}}) {
    ParticipantMain participant("turf-test", "ports");
    uint16_t p = 1;
    participant.AddPort("--port", p, "a port");
    std::vector<const char*> argv = {"turf-test"};
    for (const std::string& a : args) argv.push_back(a.c_str());
    EXPECT_EQ(participant.Run(static_cast<int>(argv.size()), argv.data(), Clean), kExitBadConfig) << args[1];
    EXPECT_EQ(p, 1) << args[1];
  }
}

// Made first in every main(), it installs the stop signals before the flags are even declared: a launcher's SIGTERM
// during start-up is a stop, not a death.
TEST(ParticipantMainSignals, TheStopSignalsAreInstalledWhenItIsMade) {
  const pid_t pid = fork();
  if (pid == 0) {
    signal(SIGTERM, SIG_DFL);  // as in a fresh process (this test's others have made one)
    ParticipantMain participant("turf-test", "turf-test: made, not run");
    struct sigaction after {};
    sigaction(SIGTERM, nullptr, &after);
    _exit(after.sa_handler != SIG_DFL && after.sa_handler != SIG_IGN ? 0 : 2);
  }
  int status = 0;
  ASSERT_EQ(waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFEXITED(status)) << status;
  EXPECT_EQ(WEXITSTATUS(status), 0);
}

TEST_F(ParticipantMainTest, DefaultsWithoutFlags) {
  participant_.AddCommonFlags(options_);
  EXPECT_EQ(Run({}, Clean), kExitClean);
  EXPECT_EQ(options_.domain, 0);
  EXPECT_EQ(options_.prefix, "turf");
  EXPECT_EQ(options_.qos_file, "");
  EXPECT_EQ(spdlog::get_level(), spdlog::level::info);
}

TEST_F(ParticipantMainTest, DomainOutOfRangeExits2WithoutRunningTheBody) {
  participant_.AddCommonFlags(options_);
  EXPECT_EQ(Run({"-d", "233"}, Clean), kExitBadConfig);
  EXPECT_EQ(body_runs_, 0);
}

TEST_F(ParticipantMainTest, EveryRefusedFlagExits2) {
  for (const std::vector<std::string>& args :
       std::vector<std::vector<std::string>>{{"-d", "-1"},
                                             {"--domain", "seven"},
                                             {"--no-such-flag"},
                                             {"--prefix"},
                                             {"--prefix", ""},
                                             {"--prefix", "a b"},
                                             {"--prefix", "team*"},
                                             {"--log-level", "loud"},
                                             {"--qos", "/nonexistent/turf_qos.xml"}}) {
    ParticipantMain participant("turf-test", "refusals");
    ParticipantOptions options;
    participant.AddCommonFlags(options);
    std::vector<const char*> argv = {"turf-test"};
    for (const std::string& a : args) argv.push_back(a.c_str());
    bool ran = false;
    EXPECT_EQ(participant.Run(static_cast<int>(argv.size()), argv.data(),
                              [&] {
                                ran = true;
                                return kExitClean;
                              }),
              kExitBadConfig)
        << args[0];
    EXPECT_FALSE(ran) << args[0];
  }
}

TEST_F(ParticipantMainTest, HelpExits0WithoutRunningTheBodyAndListsCommonFlagsInPlace) {
  std::string own;
  participant_.app().add_option("--before", own, "a participant's flag declared first");
  participant_.AddCommonFlags(options_, {"DDS domain id", "topic name prefix (for this test)"});
  participant_.app().add_option("--after", own, "a participant's flag declared after the common ones");
  testing::internal::CaptureStdout();
  const int code = Run({"--help"}, Clean);
  const std::string help = testing::internal::GetCapturedStdout();
  EXPECT_EQ(code, kExitClean);
  EXPECT_EQ(body_runs_, 0);
  EXPECT_NE(help.find("turf-test: the skeleton under test"), std::string::npos) << help;
  EXPECT_NE(help.find("topic name prefix (for this test)"), std::string::npos) << help;
  EXPECT_NE(help.find("Fast DDS XML QoS profiles"), std::string::npos) << help;
  // --help lists flags in the order they were declared; --log-level comes last.
  const std::vector<std::string> order = {"--before", "--domain", "--prefix", "--qos", "--after", "--log-level"};
  for (size_t i = 1; i < order.size(); ++i)
    EXPECT_LT(help.find(order[i - 1]), help.find(order[i])) << order[i - 1] << " before " << order[i] << "\n" << help;
}

TEST_F(ParticipantMainTest, ExceptionInTheBodyExits1) {
  EXPECT_EQ(Run({}, []() -> int { throw std::runtime_error("socket gone"); }), kExitFailure);
  EXPECT_EQ(body_runs_, 1);
  EXPECT_TRUE(Logged("socket gone"));
  EXPECT_FALSE(Logged("stopped cleanly"));
}

TEST_F(ParticipantMainTest, ExceptionThatIsNoStdExceptionExits1) {
  EXPECT_EQ(Run({}, []() -> int { throw 7; }), kExitFailure);
  EXPECT_FALSE(Logged("stopped cleanly"));
}

TEST_F(ParticipantMainTest, InvalidArgumentInTheBodyExits2) {
  EXPECT_EQ(Run({}, []() -> int { throw std::invalid_argument("bad address '1.2.3'"); }), kExitBadConfig);
  EXPECT_TRUE(Logged("bad address '1.2.3'"));
  EXPECT_FALSE(Logged("stopped cleanly"));
}

TEST_F(ParticipantMainTest, TheBodysResultIsTheExitCodeAndOnlyACleanOneSaysSo) {
  EXPECT_EQ(Run({}, [] { return kExitBadConfig; }), kExitBadConfig);
  EXPECT_FALSE(Logged("stopped cleanly"));
  ParticipantMain clean("turf-test", "clean");
  const char* argv[] = {"turf-test"};
  EXPECT_EQ(clean.Run(1, argv, Clean), kExitClean);
  EXPECT_TRUE(Logged("stopped cleanly"));
  EXPECT_TRUE(Logged("[turf-test]"));  // SetupLogging's pattern names the process
}

}  // namespace
}  // namespace turf
