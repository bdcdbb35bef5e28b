// Reading a small text file (scene, realism, robot model) for the config
// compilers, with the size capped: an error message instead of an exception.
#pragma once

#include <cstdint>
#include <string>

namespace turf {

// The whole file into *text; false with *error ("no such file", "not a regular
// file", "too large (N bytes)", ...) when it cannot or should not be read.
bool ReadTextFile(const std::string& path, uintmax_t max_bytes, std::string* text, std::string* error);

}  // namespace turf
