// turf-sim's resume file: the newest kernel snapshot of a running match, so that a turf-sim restarted after a crash
// (by `turf launch`'s supervisor) continues where it was instead of from kick-off (--resume-dir).
//
// <dir>/<prefix>.resume holds a header line ("turf-resume 1"), the scene's identity (a line) and the kernel's
// snapshot bytes (kernel/snapshot_envelope.h). It is replaced whole: written to a temporary file and renamed, so a
// crash while writing leaves the previous one. A file of another scene, a torn or foreign file is refused with the
// reason; the kernel's Restore checks the snapshot itself.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace turf {

struct ResumeRead {
  std::optional<std::string> snapshot;  // the kernel snapshot, if the file is there and is this scene's
  std::string why_not;                  // when there is a file but it cannot be used
};

// The file's path for the match on topic prefix `prefix`.
std::string ResumePath(const std::string& dir, const std::string& prefix);
// Replaces the file; "" on success, else why (the previous file is then left as it was).
std::string WriteResumeFile(const std::string& path, std::string_view identity, std::string_view snapshot);
// Reads the file if there is one. A missing file is no error (a first start).
ResumeRead ReadResumeFile(const std::string& path, std::string_view identity);

}  // namespace turf
