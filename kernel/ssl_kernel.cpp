#include "kernel/ssl_kernel.h"

#include "core/input_limits.h"
#include "core/rng.h"
#include "core/state_fields.h"

namespace turf {

namespace {

// A robot radio acknowledges kick requests and sends a lost one again at once,
// so link loss delays a kick by a few retries instead of losing it: a team's
// single kick command always reaches the robot (see the kicker's arm time).
constexpr int64_t kKickRetryNs = 1'000'000;
constexpr int kKickTries = 50;
constexpr size_t kMaxPendingCommands = 1 << 16;

std::string CommandStreamName(int team) { return std::string("ssl/command/") + TeamName(static_cast<Team>(team)); }

}  // namespace

SslKernel::SslKernel(Scene scene) : world_(std::move(scene)), cameras_(world_.scene()) {
  const Scene& s = world_.scene();
  for (int t = 0; t < kTeamCount; ++t)
    command_links_.emplace_back(s.realism.command, StreamSeed(s.seed, CommandStreamName(t)));
  SetRealism(s.realism);
  Reset();
}

InputError SslKernel::CheckCommandInput(Team topic_team, const RobotCommand& c) const {
  if (c.team != topic_team) return InputError::kTeamMismatch;
  if (world_.RobotIndex(c.team, c.id) < 0) return InputError::kUnknownRobot;
  return CheckCommand(c);
}

InputError SslKernel::Command(Team topic_team, const RobotCommand& c) {
  if (const InputError e = CheckCommandInput(topic_team, c); e != InputError::kOk) return e;
  // Valid: now it travels the team's modelled radio link (which may lose it).
  const int t = static_cast<int>(c.team);
  command_stats_[t].Sent();
  const bool kick = c.kick != KickKind::kNone && c.kick_speed > 0.0;
  const std::optional<int64_t> due = kick ? command_links_[t].TransmitAcknowledged(time_ns(), kKickRetryNs, kKickTries)
                                          : command_links_[t].Transmit(time_ns());
  if (!due) {
    command_stats_[t].Lost();
    return InputError::kOk;
  }
  if (pending_[t].size() >= kMaxPendingCommands) pending_[t].pop_front();  // a flood ages out
  pending_[t].push_back({*due, time_ns(), c});
  return InputError::kOk;
}

InputError SslKernel::TeleportBall(const BallTeleport& teleport) {
  const InputError e = world_.TeleportBall(teleport);
  world_.Snapshot(&state_);
  return e;
}

InputError SslKernel::TeleportRobot(const RobotTeleport& teleport) {
  const InputError e = world_.TeleportRobot(teleport);
  world_.Snapshot(&state_);
  return e;
}

std::string SslKernel::SetRealism(const SensorRealism& realism) {
  if (const char* e = CheckRealism(realism); *e != '\0') return e;
  realism_ = realism;
  cameras_.SetRealism(realism.camera);
  for (Link& link : command_links_) link.SetParams(realism.command);
  return "";
}

void SslKernel::Reset() {
  world_.Reset();
  cameras_.Reset();
  for (int t = 0; t < kTeamCount; ++t) {
    command_links_[t].Reset(StreamSeed(scene().seed, CommandStreamName(t)));
    pending_[t].clear();
    command_stats_[t] = StreamStats{};
  }
  stats_.Reset();
  world_.Snapshot(&state_);
  last_feedback_ = state_.robots;
  camera_frames_.clear();
  feedback_.clear();
}

void SslKernel::Step() {
  StagePre();
  world_.Step();
  StagePost();
}

// Commands whose modelled radio delay has passed reach their robots.
void SslKernel::StagePre() {
  for (int t = 0; t < kTeamCount; ++t) {
    auto& queue = pending_[t];
    while (!queue.empty() && queue.front().due_ns <= time_ns()) {
      world_.SetCommand(queue.front().command);  // validated on arrival
      command_stats_[t].Delivered((time_ns() - queue.front().sent_ns) * 1e-9);
      queue.pop_front();
    }
  }
}

void SslKernel::StagePost() {
  world_.Snapshot(&state_);
  if (cameras_.Due(time_ns())) cameras_.Capture(state_);
  cameras_.Release(time_ns(), &camera_frames_);
  CollectFeedback();
  CollectStats();
}

void SslKernel::CollectFeedback() {
  feedback_.clear();
  for (size_t i = 0; i < state_.robots.size(); ++i) {
    const RobotSnapshot& now = state_.robots[i];
    RobotSnapshot& last = last_feedback_[i];
    if (now.ball_contact == last.ball_contact && now.kick_count == last.kick_count) continue;
    feedback_.push_back(now);
    last = now;
  }
}

void SslKernel::CollectStats() {
  stats_.Collect(time_ns(), [this](StreamReport& report) {
    for (size_t c = 0; c < cameras_.cameras().size(); ++c)
      report.streams.emplace_back("ssl/camera/" + std::to_string(c), cameras_.TakeStats(static_cast<int>(c)));
    for (int t = 0; t < kTeamCount; ++t) report.streams.emplace_back(CommandStreamName(t), command_stats_[t].Take());
  });
}

// The sections before the last feedback, listed once (core/state_io.h).
template <class Io, class Self>
void SslKernel::Fields(Io& io, Self& self) {
  io(self.world_, self.cameras_, self.realism_);
  io.Tag(StateTag("RADI"));
  for (int t = 0; t < kTeamCount; ++t)
    io(self.command_links_[t], self.command_stats_[t], Sized(self.pending_[t], kMaxPendingCommands));
  io(self.stats_);
}

void SslKernel::SaveTo(StateWriter& out) const {
  Fields(out, *this);
  for (const RobotSnapshot& r : last_feedback_) out(r.ball_contact, r.kick_count);
}

void SslKernel::RestoreFrom(StateReader& in) {
  Fields(in, *this);
  world_.Snapshot(&state_);
  last_feedback_ = state_.robots;
  for (RobotSnapshot& r : last_feedback_) in(r.ball_contact, r.kick_count);
  camera_frames_.clear();
  feedback_.clear();
}

}  // namespace turf
