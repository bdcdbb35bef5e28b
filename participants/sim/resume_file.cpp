#include "participants/sim/resume_file.h"

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>

namespace turf {

namespace {

constexpr std::string_view kHeader = "turf-resume 1\n";
constexpr size_t kMaxFileBytes = 256u << 20;  // far above any scene's snapshot; a bigger file is not ours

}  // namespace

std::string ResumePath(const std::string& dir, const std::string& prefix) { return dir + "/" + prefix + ".resume"; }

std::string WriteResumeFile(const std::string& path, std::string_view identity, std::string_view snapshot) {
  if (identity.find('\n') != std::string_view::npos) return "the scene identity must be one line";
  const std::string temporary = path + ".tmp";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) return "cannot write " + temporary + ": " + std::strerror(errno);
    out << kHeader << identity << '\n';
    out.write(snapshot.data(), static_cast<std::streamsize>(snapshot.size()));
    out.flush();
    if (!out) return "cannot write " + temporary + ": " + std::strerror(errno);
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) return "cannot replace " + path + ": " + std::strerror(errno);
  return "";
}

ResumeRead ReadResumeFile(const std::string& path, std::string_view identity) {
  ResumeRead out;
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) return out;  // none yet
  // Its size first: a file larger than any snapshot is refused before it is read.
  const std::streamoff size = in.tellg();
  if (size < 0) {
    out.why_not = "cannot tell the size of " + path;
    return out;
  }
  if (static_cast<uint64_t>(size) > kMaxFileBytes) {
    out.why_not = path + " is larger than any turf snapshot";
    return out;
  }
  in.seekg(0);
  std::string file(static_cast<size_t>(size), '\0');
  if (!in.read(file.data(), size)) {
    out.why_not = "cannot read " + path;
    return out;
  }
  if (file.compare(0, kHeader.size(), kHeader) != 0) {
    out.why_not = path + " is not a turf resume file";
    return out;
  }
  const size_t end_of_identity = file.find('\n', kHeader.size());
  if (end_of_identity == std::string::npos) {
    out.why_not = path + " is cut short";
    return out;
  }
  const std::string_view saved(file.data() + kHeader.size(), end_of_identity - kHeader.size());
  if (saved != identity) {
    out.why_not = path + " is of another match (" + std::string(saved) + ", not " + std::string(identity) + ")";
    return out;
  }
  out.snapshot = file.substr(end_of_identity + 1);
  return out;
}

}  // namespace turf
