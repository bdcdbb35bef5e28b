#include "participants/sim/applied_inputs.h"

namespace turf {

AppliedInputsLog::AppliedInputsLog(dds::Bus& bus) : writer_(bus.MakeWriter(dds::Topic::kAppliedInputs)) {}

bool AppliedInputsLog::Read() {
  if (writer_->Matched() > 0) return true;
  unread_ = true;
  return false;
}

void AppliedInputsLog::Took(const std::string& topic, std::vector<uint8_t> cdr) {
  if (!Read()) return;
  idl::AppliedInput input;
  input.topic(topic);
  input.cdr(std::move(cdr));
  pending_.inputs().push_back(std::move(input));
}

void AppliedInputsLog::Flush(uint64_t step, int64_t sim_time_ns) {
  if (pending_.inputs().empty() && !unread_) return;
  const uint64_t number = number_++;
  if (unread_) {  // a record without all of the poll's inputs is none: not written
    unread_ = false;
    pending_.inputs().clear();
    return;
  }
  pending_.number(number);
  pending_.step(step);
  pending_.sim_time_ns(sim_time_ns);
  writer_->Write(pending_);
  pending_.inputs().clear();
}

}  // namespace turf
