// Save() and Restore() of a kernel, in the snapshot envelope of its kind
// (snapshot_envelope.h): Kernel writes its own sections in SaveTo(StateWriter&)
// and reads them back in RestoreFrom(StateReader&) (private; befriend this).
#pragma once

#include <string>
#include <string_view>

#include "kernel/snapshot_envelope.h"

namespace turf {

template <class Kernel, KernelKind kKind>
class Snapshots {
 public:
  // Every mutable part, random streams included: a restored kernel produces
  // the same outputs, byte for byte, as the saved one would.
  std::string Save() const {
    return SaveSnapshot(kKind, [this](StateWriter& out) { kernel().SaveTo(out); });
  }
  // Empty on success; else why, and the kernel is as before the call.
  std::string Restore(std::string_view snapshot) {
    return RestoreSnapshot(
        kKind, snapshot, [this](StateReader& in) { kernel().RestoreFrom(in); }, [this] { return Save(); });
  }

 private:
  const Kernel& kernel() const { return static_cast<const Kernel&>(*this); }
  Kernel& kernel() { return static_cast<Kernel&>(*this); }
};

}  // namespace turf
