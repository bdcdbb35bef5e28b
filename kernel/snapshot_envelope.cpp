#include "kernel/snapshot_envelope.h"

namespace turf {

namespace {

constexpr uint64_t kMagic = 0x50414e5346525554ull;  // "TURFSNAP" in a little-endian dump

std::string_view Body(std::string_view snapshot) { return snapshot.substr(sizeof(kMagic) + 4 + 1); }

const char* CheckEnvelope(KernelKind kind, std::string_view snapshot) {
  StateReader in(snapshot);
  if (in.Get<uint64_t>() != kMagic) return "not a turf snapshot";
  if (in.Get<uint32_t>() != kSnapshotVersion) return "snapshot format version differs";
  if (in.Get<uint8_t>() != static_cast<uint8_t>(kind)) return "snapshot of another kind of scene";
  return in.ok() ? "" : "truncated snapshot";
}

}  // namespace

std::string SaveSnapshot(KernelKind kind, const std::function<void(StateWriter&)>& save) {
  StateWriter out;
  out.Put(kMagic);
  out.Put(kSnapshotVersion);
  out.Put(kind);
  save(out);
  return out.Take();
}

std::string RestoreSnapshot(KernelKind kind, std::string_view snapshot,
                            const std::function<void(StateReader&)>& restore,
                            const std::function<std::string()>& backup) {
  if (const char* e = CheckEnvelope(kind, snapshot); *e != '\0') return e;
  const std::string before = backup();
  StateReader in(Body(snapshot));
  restore(in);
  if (in.ok() && !in.AtEnd()) in.Fail("trailing bytes");
  if (in.ok()) return "";
  const std::string why = std::string("invalid snapshot: ") + in.error();
  StateReader undo(Body(before));
  restore(undo);  // our own bytes: always whole
  return why;
}

}  // namespace turf
