#include "participants/replay/replay_control.h"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <variant>

namespace turf {

ReplayControl::ReplayControl(dds::Bus& bus)
    : reply_writer_(bus.MakeWriter(dds::Topic::kControlReply)), reader_(bus.MakeReader(dds::Topic::kControl, [this] {
        {
          std::lock_guard<std::mutex> lock(mutex_);
          pending_ = true;
        }
        arrived_.notify_all();
      })) {}

void ReplayControl::Submit(ReplayCommand command) {
  command.local = true;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    local_.push_back(std::move(command));
    pending_ = true;
  }
  arrived_.notify_all();
}

std::vector<ReplayCommand> ReplayControl::Take(int64_t sim_time_ns) {
  std::vector<ReplayCommand> commands;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    pending_ = false;
    commands.swap(local_);
  }
  std::vector<idl::SimControl> requests;
  if (!reader_->Take(&requests)) return commands;
  for (const idl::SimControl& request : requests) {
    auto command = ReplayCommandOf(request);
    if (auto* refusal = std::get_if<ReplayRefusal>(&command)) {
      ++refused_;
      spdlog::warn("refused control request {} from '{}': {}", request.request_id(), request.client(), refusal->reason);
      Reply(ReplayCommand{ReplayCommand::Kind::kPause, 1, 0, request}, sim_time_ns, *refusal);
    } else {
      commands.push_back(std::get<ReplayCommand>(std::move(command)));
    }
  }
  return commands;
}

void ReplayControl::WaitUntil(SteadyClock::time_point until) {
  std::unique_lock<std::mutex> lock(mutex_);
  arrived_.wait_until(lock, until, [this] { return pending_; });
}

void ReplayControl::Reply(const ReplayCommand& command, int64_t sim_time_ns, const ReplayRefusal& refusal) {
  if (command.local) {
    if (refusal.code != idl::CONTROL_OK) spdlog::warn("{}", refusal.reason);
    return;
  }
  const idl::SimControl& request = command.request;
  idl::SimControlReply reply;
  reply.client(request.client());
  reply.request_id(request.request_id());
  reply.op(request.op());
  reply.result(refusal.code == idl::CONTROL_OK ? idl::RESULT_OK : idl::RESULT_REJECTED);
  reply.error(refusal.code);
  reply.reason(refusal.reason);
  reply.sim_time_ns(sim_time_ns);
  reply_writer_->Write(reply);
}

}  // namespace turf
