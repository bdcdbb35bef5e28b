// An enum's names as one table in the enum's order, read both ways: EnumName(value, table) for logs and
// encoders, EnumFromName(name, table) for decoders. One table per protocol's spelling of an enum.
#pragma once

#include <cstddef>
#include <optional>
#include <string_view>

namespace turf {

// The name of `value`; `fallback` for a value past the table (an enum from a newer peer).
template <class Enum, std::size_t N>
constexpr const char* EnumName(Enum value, const char* const (&names)[N], const char* fallback = "unknown") {
  const auto i = static_cast<std::size_t>(value);
  return i < N ? names[i] : fallback;
}

// The value named `name`; nothing if the table has no such name.
template <class Enum, std::size_t N>
constexpr std::optional<Enum> EnumFromName(std::string_view name, const char* const (&names)[N]) {
  for (std::size_t i = 0; i < N; ++i)
    if (name == names[i]) return static_cast<Enum>(i);
  return std::nullopt;
}

}  // namespace turf
