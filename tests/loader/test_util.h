// Helpers shared by the config tests.
#pragma once

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <string>

#include "loader/scene_yaml.h"

namespace turf::test {

// All errors, one a line, for failure messages.
inline std::string ErrorList(const SceneLoadResult& result) {
  return fmt::format("errors:\n  {}", fmt::join(result.errors, "\n  "));
}

// A file of configs/scenes/ in the source tree.
inline std::string ScenePath(const std::string& file) {
  return std::string(TURF_SOURCE_DIR) + "/configs/scenes/" + file;
}

inline std::string ReadText(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>());
}

inline bool HasErrorContaining(const SceneLoadResult& result, const std::string& text) {
  for (const std::string& error : result.errors) {
    if (error.find(text) != std::string::npos) return true;
  }
  return false;
}

}  // namespace turf::test
