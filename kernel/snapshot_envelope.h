// The envelope of a kernel snapshot: magic, format version and kernel kind
// before the kernel's own sections, and a restore that is all or nothing.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <string_view>

#include "core/state_io.h"

namespace turf {

enum class KernelKind : uint8_t { kSsl = 1, kLegged = 2 };

inline constexpr uint32_t kSnapshotVersion = 6;  // 6: a legged snapshot carries its sensor noise's seed

std::string SaveSnapshot(KernelKind kind, const std::function<void(StateWriter&)>& save);

// Checks the envelope, then reads the body with `restore`. If anything is
// wrong (another kind or version, truncated, trailing bytes, a value out of
// range) the state saved by `backup` (taken before) is restored and the
// reason returned; empty on success.
std::string RestoreSnapshot(KernelKind kind, std::string_view snapshot,
                            const std::function<void(StateReader&)>& restore,
                            const std::function<std::string()>& backup);

}  // namespace turf
