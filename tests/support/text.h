// Small string helpers for tests: golden bytes written as numbers, and what a text holds.
#pragma once

#include <gtest/gtest.h>

#include <cstddef>
#include <initializer_list>
#include <string>

namespace turf::test {

// The bytes given as numbers (0 to 255), as a string.
inline std::string Bytes(std::initializer_list<int> bytes) {
  std::string s;
  for (int b : bytes) s.push_back(static_cast<char>(b));
  return s;
}

// How often `part` occurs in `text` (overlapping occurrences count).
inline size_t Occurrences(const std::string& text, const std::string& part) {
  size_t n = 0;
  for (size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++n;
  return n;
}

// Every one of `parts` occurs in `text`; else the failure names the first missing one and shows the text.
inline ::testing::AssertionResult ContainsAll(const std::string& text, std::initializer_list<const char*> parts) {
  for (const char* part : parts)
    if (text.find(part) == std::string::npos)
      return ::testing::AssertionFailure() << "no '" << part << "' in:\n" << text;
  return ::testing::AssertionSuccess();
}

}  // namespace turf::test
