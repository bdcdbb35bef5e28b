#include "participants/replay/line_reader.h"

#include <poll.h>
#include <unistd.h>

#include <cerrno>

namespace turf {

LineReader::LineReader(int fd, size_t max_line, std::function<void(std::string_view)> on_line)
    : fd_(fd), max_line_(max_line), on_line_(std::move(on_line)), thread_([this] { Run(); }) {}

LineReader::~LineReader() {
  stop_.store(true);
  thread_.join();
}

void LineReader::Run() {
  char buffer[512];
  while (!stop_.load()) {
    pollfd p{fd_, POLLIN, 0};
    const int ready = ::poll(&p, 1, 100);
    if (ready < 0 && errno == EINTR) continue;
    if (ready < 0) return;
    if (ready == 0) continue;
    const ssize_t n = ::read(fd_, buffer, sizeof buffer);
    if (n < 0 && (errno == EINTR || errno == EAGAIN)) continue;
    if (n <= 0) return;  // end of file (e.g. /dev/null) or an error: no more commands
    Consume(buffer, static_cast<size_t>(n));
  }
}

void LineReader::Consume(const char* data, size_t size) {
  for (size_t i = 0; i < size; ++i) {
    if (data[i] != '\n') {
      if (line_.size() <= max_line_) line_.push_back(data[i]);
      continue;
    }
    on_line_(line_);
    line_.clear();
  }
}

}  // namespace turf
