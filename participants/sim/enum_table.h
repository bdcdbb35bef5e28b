// An enum that crosses the IDL boundary as one table of (IDL constant, turf value) pairs, read both ways, instead
// of a switch per direction (convert.cpp, legged_convert.cpp). Header-only.
#pragma once

#include <cstddef>
#include <utility>

namespace turf {

// `value`'s turf counterpart into `out`; false (out untouched) for a value the table does not have, e.g. an
// out-of-range number from a DDS sample.
template <class Idl, class Turf, std::size_t N>
bool FromIdlEnum(const std::pair<Idl, Turf> (&table)[N], Idl value, Turf* out) {
  for (const auto& [idl, turf] : table) {
    if (idl != value) continue;
    *out = turf;
    return true;
  }
  return false;
}

// `value`'s IDL counterpart; `fallback` for a value the table does not have.
template <class Idl, class Turf, std::size_t N>
Idl ToIdlEnum(const std::pair<Idl, Turf> (&table)[N], Turf value, Idl fallback) {
  for (const auto& [idl, turf] : table)
    if (turf == value) return idl;
  return fallback;
}

}  // namespace turf
