// Reading turf's own source files in tests: tables that are generated from code (README's topic and realism
// tables) and files tests check against code (the IDL, the QoS profiles). Needs TURF_SOURCE_DIR.
#pragma once

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

namespace turf::test {

// A file of the source tree, by its path from the top ("README.md"); empty if it cannot be read.
inline std::string SourceFile(const std::string& path) {
  std::ifstream in(std::string(TURF_SOURCE_DIR) + "/" + path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// README.md holds `expected` between the line `begin` (with its newline) and `end`, once. On failure the message
// shows the text to paste between the markers.
inline ::testing::AssertionResult ReadmeSectionIs(const std::string& begin, const std::string& end,
                                                  const std::string& expected) {
  const std::string readme = SourceFile("README.md");
  const size_t from = readme.find(begin);
  if (from == std::string::npos) return ::testing::AssertionFailure() << "README.md has no line " << begin;
  const size_t to = readme.find(end, from);
  if (to == std::string::npos)
    return ::testing::AssertionFailure() << "README.md has no line " << end << " after " << begin;
  if (readme.find(begin, from + 1) != std::string::npos)
    return ::testing::AssertionFailure() << "README.md has the line " << begin << " twice";
  if (readme.substr(from + begin.size(), to - from - begin.size()) != expected)
    return ::testing::AssertionFailure() << "README.md's section is not the generated one; between the markers it "
                                            "should read:\n"
                                         << begin << expected << end;
  return ::testing::AssertionSuccess();
}

}  // namespace turf::test
