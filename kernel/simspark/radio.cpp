#include "kernel/simspark/radio.h"

#include <algorithm>
#include <cmath>

namespace turf::simspark {

void Radio::Say(const Speaker& who, const std::string& message, double game_time) {
  // One message per speaker and cycle, the last one (the reference's SayEffector::Realize overwrites its message).
  for (Said& said : said_) {
    if (said.speaker.side == who.side && said.speaker.unum == who.unum) {
      said = {who, message, game_time};
      return;
    }
  }
  said_.push_back({who, message, game_time});
}

std::vector<Heard> Radio::Deliver(const Speaker& listener, uint64_t cycle) {
  const auto key = std::make_pair(static_cast<int>(listener.side), listener.unum);
  auto [it, inserted] = capacity_.try_emplace(key);
  Capacity& cap = it->second;
  if (inserted) {
    cap = {params_.capacity_max, params_.capacity_max, cycle};
  } else if (cycle > cap.cycle) {
    const uint64_t gained = (cycle - cap.cycle) * static_cast<uint64_t>(params_.capacity_gain);
    const auto refill = [&](int value) {
      return static_cast<int>(std::min<uint64_t>(params_.capacity_max, value + gained));
    };
    cap.teammates = refill(cap.teammates);
    cap.opponents = refill(cap.opponents);
    cap.cycle = cycle;
  }

  // The reference's HearPerceptor::Percept writes its own message first, then
  // the teammate's, then the opponent's.
  std::vector<Heard> heard;
  std::vector<Heard> teammates;
  std::vector<Heard> opponents;
  for (const Said& said : said_) {
    const Speaker& speaker = said.speaker;
    if (speaker.side == listener.side && speaker.unum == listener.unum) {
      heard.push_back({speaker.team, said.game_time, true, 0.0, said.message});
      continue;
    }
    const Eigen::Vector3d relative = speaker.position - listener.position;
    if (relative.norm() > params_.max_distance) continue;
    const bool teammate = speaker.side == listener.side;
    int& budget = teammate ? cap.teammates : cap.opponents;
    if (budget < params_.capacity_cost) continue;
    budget -= params_.capacity_cost;
    Eigen::Vector2d delta = relative.head<2>();
    if (listener.side == Side::kRight) delta = -delta;
    const double direction = std::atan2(delta.y(), delta.x()) * 180.0 / M_PI;
    (teammate ? teammates : opponents).push_back({speaker.team, said.game_time, false, direction, said.message});
  }
  heard.insert(heard.end(), teammates.begin(), teammates.end());
  heard.insert(heard.end(), opponents.begin(), opponents.end());
  return heard;
}

void Radio::EndCycle() { said_.clear(); }

void Radio::Forget(Side side, int unum) { capacity_.erase(std::make_pair(static_cast<int>(side), unum)); }

}  // namespace turf::simspark

namespace turf::simspark {

namespace {

constexpr size_t kMaxSaid = 1024;       // speakers in one cycle
constexpr size_t kMaxListeners = 1024;  // capacities kept

}  // namespace

void Radio::Save(StateWriter& out) const {
  out.Tag(StateTag("SRAD"));
  out(Sized(said_, kMaxSaid), Sized(capacity_, kMaxListeners));
}

void Radio::Restore(StateReader& in) {
  in.Tag(StateTag("SRAD"));
  std::vector<Said> said;
  std::map<std::pair<int, int>, Capacity> capacity;
  in(Sized(said, kMaxSaid), Sized(capacity, kMaxListeners));
  for (const auto& [listener, cap] : capacity) {
    if (listener.first < 0 || listener.first > 1) in.Fail("enum value out of range");
    if (cap.teammates < 0 || cap.opponents < 0 || cap.teammates > params_.capacity_max ||
        cap.opponents > params_.capacity_max)
      in.Fail("radio capacity out of range");
  }
  if (!in.ok()) return;
  said_ = std::move(said);
  capacity_ = std::move(capacity);
}

}  // namespace turf::simspark
