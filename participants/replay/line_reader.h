// Lines from a file descriptor (turf-replay: its standard input) on a thread of their own, handed to a callback.
// Stops at end of file, on a read error, or when destroyed (poll wakes every 100 ms to notice). A line longer than
// `max_line` is handed over cut to max_line + 1 bytes, so the callback can refuse it; the rest of it is dropped.
#pragma once

#include <atomic>
#include <functional>
#include <string>
#include <string_view>
#include <thread>

namespace turf {

class LineReader {
 public:
  LineReader(int fd, size_t max_line, std::function<void(std::string_view)> on_line);
  ~LineReader();
  LineReader(const LineReader&) = delete;
  LineReader& operator=(const LineReader&) = delete;

 private:
  void Run();
  void Consume(const char* data, size_t size);

  const int fd_;
  const size_t max_line_;
  std::function<void(std::string_view)> on_line_;
  std::string line_;
  std::atomic<bool> stop_{false};
  std::thread thread_;  // last: started once the members above exist
};

}  // namespace turf
