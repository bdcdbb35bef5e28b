#include "participants/common/mcap_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace turf {

McapFileSource::McapFileSource(const std::string& path) {
  fd_ = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  struct stat st {};
  if (fd_ < 0 || ::fstat(fd_, &st) != 0 || !S_ISREG(st.st_mode)) {
    error_ = path + ": " + (fd_ < 0 ? std::strerror(errno) : "not a regular file");
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
    return;
  }
  size_ = static_cast<uint64_t>(st.st_size);
}

McapFileSource::~McapFileSource() {
  if (fd_ >= 0) ::close(fd_);
}

bool McapFileSource::Read(uint64_t offset, size_t n, std::string* out) const {
  if (fd_ < 0 || offset > size_ || n > size_ - offset) return false;
  out->resize(n);
  size_t done = 0;
  while (done < n) {
    const ssize_t r = ::pread(fd_, out->data() + done, n - done, static_cast<off_t>(offset + done));
    if (r < 0 && errno == EINTR) continue;
    if (r <= 0) return false;
    done += static_cast<size_t>(r);
  }
  return true;
}

McapFileSink::McapFileSink(const std::string& path) {
  fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd_ < 0) error_ = path + ": " + std::strerror(errno);
}

McapFileSink::~McapFileSink() {
  Flush();
  if (fd_ >= 0) ::close(fd_);
}

void McapFileSink::Write(std::string_view bytes) {
  buffer_.append(bytes);
  if (buffer_.size() >= (1u << 20)) Flush();
}

void McapFileSink::Flush() {
  size_t done = 0;
  while (fd_ >= 0 && error_.empty() && done < buffer_.size()) {
    const ssize_t w = ::write(fd_, buffer_.data() + done, buffer_.size() - done);
    if (w < 0 && errno == EINTR) continue;
    if (w < 0) error_ = std::string("write: ") + std::strerror(errno);
    if (w > 0) done += static_cast<size_t>(w);
  }
  buffer_.clear();
}

}  // namespace turf
