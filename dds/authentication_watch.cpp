#include "dds/authentication_watch.h"

#include <spdlog/spdlog.h>

namespace turf::dds {

AuthenticationTimer::AuthenticationTimer(AuthenticationWatch& watch) : watch_(watch), thread_([this] { Run(); }) {}

AuthenticationTimer::~AuthenticationTimer() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

void AuthenticationTimer::Run() {
  const double timeout_s = std::chrono::duration<double>(watch_.timeout()).count();
  std::unique_lock<std::mutex> lock(mutex_);
  while (!wake_.wait_for(lock, std::chrono::milliseconds(500), [this] { return stop_; })) {
    for (const PeerInfo& peer : watch_.Overdue(AuthenticationWatch::Clock::now()))
      spdlog::warn(
          "DDS security: {} was discovered more than {:.0f} s ago and has not finished authenticating with this "
          "participant: "
          "no topic flows between the two. Fast DDS 2.9.1 sometimes never finishes a handshake (README, Access "
          "control: known limit); restart this process or that one",
          peer.Describe(), timeout_s);
  }
}

}  // namespace turf::dds
