// An object's snapshot (its Save(StateWriter&)) as bytes, and bytes restored into an object
// (Restore(StateReader&)): for the round-trip and damaged-snapshot tests of the kernels' parts.
#pragma once

#include <string>

#include "core/state_io.h"

namespace turf::test {

template <class T>
std::string Saved(const T& object) {
  StateWriter out;
  object.Save(out);
  return out.Take();
}

// "" when `bytes` were taken whole (read to the end), else why not.
template <class T>
std::string RestoreAll(const std::string& bytes, T* object) {
  StateReader in(bytes);
  object->Restore(in);
  if (!in.ok()) return in.error();
  return in.AtEnd() ? "" : "bytes left over";
}

}  // namespace turf::test
