// dds::FanoutBus: one Bus (bus.h) over two, so that a participant is on both at once: turf-sim on Fast DDS for
// remote participants and on a MemoryBus for front-ends served in its own process (the SSL sync port), which then
// pay no DDS round trip.
//
//  - a writer writes each sample to both buses (true only if both took it);
//  - a reader takes what arrives on either bus into its one queue (on_data runs on either bus's delivery thread);
//  - Matched() and DeadlinesMissed() add up both sides.
// No sample is seen twice as long as every other endpoint is on one of the two buses only: an in-process front-end
// on the MemoryBus, remote participants on DDS. (A process on both buses with endpoints of its own on each would
// see its samples once per bus.) The two buses must have the same topic prefix and outlive this bus.
#pragma once

#include <memory>
#include <string>

#include "dds/bus.h"

namespace turf::dds {

class FanoutBus final : public Bus {
 public:
  // Throws std::invalid_argument if the two prefixes differ.
  FanoutBus(Bus& first, Bus& second);
  ~FanoutBus() override;

  Bus& first() { return first_; }
  Bus& second() { return second_; }
  // "<first> and <second>".
  std::string Describe() const override;

 protected:
  std::unique_ptr<WriterEndpoint> OpenWriter(Topic topic, const SampleOps& ops) override;
  std::unique_ptr<ReaderEndpoint> OpenReader(Topic topic, const SampleOps& ops, SampleSink& sink) override;

 private:
  Bus& first_;
  Bus& second_;
};

}  // namespace turf::dds
