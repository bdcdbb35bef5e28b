#include "participants/sim/applied_inputs.h"

namespace turf {

AppliedInputsLog::AppliedInputsLog(dds::Bus& bus) : writer_(bus.MakeWriter(dds::Topic::kAppliedInputs)) {}

void AppliedInputsLog::Took(const std::string& topic, std::vector<uint8_t> cdr) {
  idl::AppliedInput input;
  input.topic(topic);
  input.cdr(std::move(cdr));
  pending_.inputs().push_back(std::move(input));
}

void AppliedInputsLog::Flush(uint64_t step, int64_t sim_time_ns) {
  if (pending_.inputs().empty()) return;
  pending_.number(number_++);
  pending_.step(step);
  pending_.sim_time_ns(sim_time_ns);
  writer_->Write(pending_);
  pending_.inputs().clear();
}

}  // namespace turf
