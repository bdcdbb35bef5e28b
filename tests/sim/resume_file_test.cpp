// turf-sim's resume file (participants/sim/resume_file.h): what a restarted turf-sim accepts and refuses.
#include "participants/sim/resume_file.h"

#include <gtest/gtest.h>
#include <sys/resource.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace turf {
namespace {

class ResumeFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() / ("turf_resume_test_" + std::to_string(getpid()));
    std::filesystem::create_directories(dir_);
    path_ = ResumePath(dir_.string(), "match");
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  void WriteRaw(const std::string& bytes) { std::ofstream(path_, std::ios::binary) << bytes; }

  std::filesystem::path dir_;
  std::string path_;
};

TEST_F(ResumeFileTest, NoFileIsAFirstStartNotAnError) {
  const ResumeRead r = ReadResumeFile(path_, "ssl scene 'a' seed 1");
  EXPECT_FALSE(r.snapshot.has_value());
  EXPECT_EQ(r.why_not, "");
}

TEST_F(ResumeFileTest, ReadsBackWhatWasWrittenForTheSameScene) {
  const std::string snapshot("\x00\x01 bytes\nwith newlines\xff", 24);
  ASSERT_EQ(WriteResumeFile(path_, "ssl scene 'a' seed 1", snapshot), "");
  const ResumeRead r = ReadResumeFile(path_, "ssl scene 'a' seed 1");
  ASSERT_TRUE(r.snapshot.has_value()) << r.why_not;
  EXPECT_EQ(*r.snapshot, snapshot);
  EXPECT_FALSE(std::filesystem::exists(path_ + ".tmp"));
}

TEST_F(ResumeFileTest, ANewerSnapshotReplacesTheOlder) {
  ASSERT_EQ(WriteResumeFile(path_, "id", "first"), "");
  ASSERT_EQ(WriteResumeFile(path_, "id", "second"), "");
  EXPECT_EQ(ReadResumeFile(path_, "id").snapshot.value_or(""), "second");
}

TEST_F(ResumeFileTest, AnotherScenesFileIsRefusedWithBothNamed) {
  ASSERT_EQ(WriteResumeFile(path_, "ssl scene 'a' seed 1", "x"), "");
  const ResumeRead r = ReadResumeFile(path_, "ssl scene 'a' seed 2");
  EXPECT_FALSE(r.snapshot.has_value());
  EXPECT_NE(r.why_not.find("seed 1"), std::string::npos) << r.why_not;
  EXPECT_NE(r.why_not.find("seed 2"), std::string::npos) << r.why_not;
}

TEST_F(ResumeFileTest, ForeignOrTornFilesAreRefused) {
  WriteRaw("something else entirely");
  EXPECT_FALSE(ReadResumeFile(path_, "id").snapshot.has_value());
  EXPECT_NE(ReadResumeFile(path_, "id").why_not, "");
  WriteRaw("turf-resume 1\nid without its end of line");
  EXPECT_FALSE(ReadResumeFile(path_, "id").snapshot.has_value());
  EXPECT_NE(ReadResumeFile(path_, "id").why_not.find("cut short"), std::string::npos);
}

// Refused by its size before it is read: a 400 MB file (sparse, so no disk is used) never enters memory.
TEST_F(ResumeFileTest, AFileLargerThanAnySnapshotIsRefusedUnread) {
  WriteRaw(std::string("turf resume"));
  std::filesystem::resize_file(path_, 400u << 20);
  rusage before{};
  ASSERT_EQ(getrusage(RUSAGE_SELF, &before), 0);
  const ResumeRead r = ReadResumeFile(path_, "id");
  rusage after{};
  ASSERT_EQ(getrusage(RUSAGE_SELF, &after), 0);
  EXPECT_FALSE(r.snapshot.has_value());
  EXPECT_NE(r.why_not.find("larger than any turf snapshot"), std::string::npos) << r.why_not;
  EXPECT_LT(after.ru_maxrss - before.ru_maxrss, 64 * 1024) << "peak resident KB grew while refusing it";
}

TEST_F(ResumeFileTest, AnIdentityOfSeveralLinesIsNotWritten) {
  EXPECT_NE(WriteResumeFile(path_, "two\nlines", "x"), "");
  EXPECT_FALSE(std::filesystem::exists(path_));
}

}  // namespace
}  // namespace turf
