// Under DDS Security no topic flows between two participants until they have authenticated each other. Fast DDS
// 2.9.1 (Debian 12) sometimes never finishes one pair's handshake and says nothing (README, Access control: known
// limit). The watch keeps the participants discovered whose authentication has not ended, so that one still pending
// after `timeout` is named in a warning (AuthenticationTimer). Internal to dds/; no Fast DDS in it.
//
// Thread-safe: Fast DDS's threads tell it of discoveries and authentications (dds/participant.cpp), a timer asks
// what is overdue.
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "dds/participant.h"

namespace turf::dds {

class AuthenticationWatch {
 public:
  using Clock = std::chrono::steady_clock;
  // At most this many participants are kept pending (announcements are unauthenticated: anyone can make up more).
  static constexpr size_t kMaxPending = 1024;

  explicit AuthenticationWatch(Clock::duration timeout) : timeout_(timeout) {}

  // `peer` announced itself for the first time at `now` (Fast DDS tells of a participant before it starts the
  // handshake): its authentication starts.
  void Discovered(const PeerInfo& peer, Clock::time_point now) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (pending_.size() < kMaxPending) pending_.emplace(peer.guid_prefix, Entry{peer, now, false});
  }
  // Its authentication ended, authorized or refused: the participant as discovered (nullopt if it was not pending).
  std::optional<PeerInfo> Ended(const std::string& guid_prefix) {
    std::lock_guard<std::mutex> lock(mutex_);
    auto it = pending_.find(guid_prefix);
    if (it == pending_.end()) return std::nullopt;
    PeerInfo peer = std::move(it->second.peer);
    pending_.erase(it);
    ++ended_;
    return peer;
  }
  // It left, or stopped announcing itself for its lease.
  void Gone(const std::string& guid_prefix) {
    std::lock_guard<std::mutex> lock(mutex_);
    pending_.erase(guid_prefix);
  }

  // The participants pending for `timeout` or longer at `now` that were not told before: each is told once.
  std::vector<PeerInfo> Overdue(Clock::time_point now) {
    std::lock_guard<std::mutex> lock(mutex_);
    std::vector<PeerInfo> out;
    for (auto& [guid, p] : pending_) {
      if (p.told || now - p.since < timeout_) continue;
      p.told = true;
      ++stalled_;
      out.push_back(p.peer);
    }
    return out;
  }
  // Participants discovered whose authentication has not ended.
  size_t Pending() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return pending_.size();
  }
  // Participants whose authentication ended after they were discovered.
  uint64_t Ended() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return ended_;
  }
  // Participants Overdue has told of.
  uint64_t Stalled() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return stalled_;
  }
  Clock::duration timeout() const { return timeout_; }

 private:
  struct Entry {
    PeerInfo peer;
    Clock::time_point since;
    bool told;
  };
  const Clock::duration timeout_;
  mutable std::mutex mutex_;
  std::map<std::string, Entry> pending_;  // by GUID prefix
  uint64_t ended_ = 0;
  uint64_t stalled_ = 0;
};

// Every half second, warns of each participant `watch` finds overdue (once each). The thread stops with it.
class AuthenticationTimer {
 public:
  explicit AuthenticationTimer(AuthenticationWatch& watch);
  ~AuthenticationTimer();
  AuthenticationTimer(const AuthenticationTimer&) = delete;
  AuthenticationTimer& operator=(const AuthenticationTimer&) = delete;

 private:
  void Run();

  AuthenticationWatch& watch_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stop_ = false;
  std::thread thread_;
};

}  // namespace turf::dds
