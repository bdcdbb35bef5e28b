// `turf log info`: the report of a file written by our MCAP writer (counts, sizes, compression, sim time), of a
// cut file (what it holds and the damage's offset), and the command's exit statuses.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <chrono>
#include <fstream>

#include "codecs/mcap/writer.h"
#include "participants/launcher/log_info.h"
#include "tests/support/process.h"
#include "tests/support/text.h"

namespace turf::launch {
namespace {

std::string Recording(mcap::Compression compression) {
  mcap::StringSink sink;
  mcap::WriterOptions options;
  options.compression = compression;
  options.chunk_size = 256;
  mcap::Writer w(&sink, options);
  const uint16_t schema = w.AddSchema("turf::idl::Clock", "omgidl", "module turf { };");
  w.AddChannel(schema, "turf/clock", "cdr");
  w.AddChannel(schema, "turf/world_state", "cdr");
  for (int i = 0; i < 100; ++i) {  // 1 s of receive time, sim time 0..1.98 s
    const uint64_t log_time = 1'000'000'000'000ull + static_cast<uint64_t>(i) * 10'000'000ull;
    w.Write(static_cast<uint16_t>(1 + i % 2), static_cast<uint32_t>(i), log_time,
            static_cast<uint64_t>(i) * 20'000'000ull, std::string(i % 2 == 0 ? 10 : 30, 'x'));
  }
  w.Close();
  return sink.bytes();
}

TEST(LogInfo, ReportsCountsSizesDurationAndCompression) {
  const std::string file = Recording(mcap::Compression::kZstd);
  const LogInfo info = ReadLogInfo("x.mcap", mcap::StringSource(file));
  ASSERT_TRUE(info.scan.ok()) << info.scan.Describe();
  EXPECT_TRUE(info.summary.ok()) << info.summary.Describe();
  const std::string text = FormatLogInfo(info);
  EXPECT_TRUE(turf::test::ContainsAll(text, {"messages:    100\n", "duration:    0.990 s",
                                             "sim time:    0.000 s to 1.980 s", "(zstd: ", "turf/clock", "50 msgs",
                                             "500 B",   // 50 x 10 bytes
                                             "1500 B",  // 50 x 30 bytes
                                             "turf::idl::Clock [omgidl] cdr", "summary:     ok"}));
}

TEST(LogInfo, ACutFileShowsWhatItHoldsAndWhere) {
  const std::string file = Recording(mcap::Compression::kNone);
  const std::string cut = file.substr(0, file.size() / 2);
  const LogInfo info = ReadLogInfo("cut.mcap", mcap::StringSource(cut));
  EXPECT_EQ(info.scan.error, mcap::ReadError::kTruncated);
  EXPECT_GT(info.scanned.statistics.message_count, 10u);
  EXPECT_LT(info.scanned.statistics.message_count, 100u);
  const std::string text = FormatLogInfo(info);
  EXPECT_NE(text.find("read:        up to offset "), std::string::npos) << text;
  EXPECT_NE(text.find("truncated at offset"), std::string::npos) << text;
}

int RunTurfLogInfo(const std::string& path, const std::string& name) {
  test::Process p(name, {test::Built("participants/launcher/turf"), "log", "info", path});
  const std::optional<int> status = p.Wait(std::chrono::seconds(20));
  EXPECT_TRUE(status.has_value());
  return status && WIFEXITED(*status) ? WEXITSTATUS(*status) : -1;
}

TEST(LogInfoCli, ExitStatusSaysWhetherTheFileIsWhole) {
  const std::string file = Recording(mcap::Compression::kZstd);
  const std::string dir = test::LogDir();
  std::ofstream(dir + "/log_info_whole.mcap", std::ios::binary) << file;
  std::ofstream(dir + "/log_info_cut.mcap", std::ios::binary) << file.substr(0, file.size() - 40);
  std::ofstream(dir + "/log_info_not.mcap", std::ios::binary) << "hello";
  EXPECT_EQ(RunTurfLogInfo(dir + "/log_info_whole.mcap", "log_info_whole"), 0);
  EXPECT_EQ(RunTurfLogInfo(dir + "/log_info_cut.mcap", "log_info_cut"), 1);
  EXPECT_EQ(RunTurfLogInfo(dir + "/log_info_not.mcap", "log_info_not"), 2);
  EXPECT_EQ(RunTurfLogInfo(dir + "/log_info_missing.mcap", "log_info_missing"), 2);
}

}  // namespace
}  // namespace turf::launch
