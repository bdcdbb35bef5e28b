// Parsing a flag set in a test: CLI11 on an argument list, with the refusal as false rather than an exception.
#pragma once

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace turf::test {

// Parses `args` (the program's name not included) with `app`; false if CLI11 refuses them.
inline bool ParseArgs(CLI::App& app, std::vector<std::string> args) {
  args.insert(args.begin(), "program");
  std::vector<const char*> argv;
  for (const std::string& a : args) argv.push_back(a.c_str());
  try {
    app.parse(static_cast<int>(argv.size()), argv.data());
    return true;
  } catch (const CLI::ParseError&) {
    return false;
  }
}

}  // namespace turf::test
