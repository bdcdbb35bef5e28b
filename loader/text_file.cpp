#include "loader/text_file.h"

#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <iterator>

namespace turf {

bool ReadTextFile(const std::string& path, uintmax_t max_bytes, std::string* text, std::string* error) {
  std::error_code ec;
  const std::filesystem::file_status status = std::filesystem::status(path, ec);
  if (status.type() == std::filesystem::file_type::not_found) {
    *error = "no such file";
    return false;
  }
  if (ec) {
    *error = fmt::format("cannot read: {}", ec.message());
    return false;
  }
  if (!std::filesystem::is_regular_file(status)) {
    *error = "not a regular file";
    return false;
  }
  const uintmax_t size = std::filesystem::file_size(path, ec);
  if (ec || size > max_bytes) {
    *error = ec ? fmt::format("cannot read: {}", ec.message()) : fmt::format("too large ({} bytes)", size);
    return false;
  }
  std::ifstream file(path, std::ios::binary);
  if (!file.is_open()) {
    *error = "cannot open the file";
    return false;
  }
  text->assign(std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>());
  if (file.bad()) {
    *error = "cannot read the file";
    return false;
  }
  return true;
}

}  // namespace turf
