#include "dds/fanout_bus.h"

#include <stdexcept>
#include <utility>

namespace turf::dds {

namespace {

class FanoutWriter final : public WriterEndpoint {
 public:
  FanoutWriter(std::unique_ptr<WriterEndpoint> a, std::unique_ptr<WriterEndpoint> b)
      : a_(std::move(a)), b_(std::move(b)) {}
  bool Write(const void* sample, std::optional<int64_t> source_ns) override {
    const bool a = a_->Write(sample, source_ns);
    const bool b = b_->Write(sample, source_ns);
    return a && b;
  }
  int Matched() const override { return a_->Matched() + b_->Matched(); }

 private:
  std::unique_ptr<WriterEndpoint> a_;
  std::unique_ptr<WriterEndpoint> b_;
};

class FanoutReader final : public ReaderEndpoint {
 public:
  FanoutReader(std::unique_ptr<ReaderEndpoint> a, std::unique_ptr<ReaderEndpoint> b)
      : a_(std::move(a)), b_(std::move(b)) {}
  int Matched() const override { return a_->Matched() + b_->Matched(); }
  int DeadlinesMissed() const override { return a_->DeadlinesMissed() + b_->DeadlinesMissed(); }

 private:
  std::unique_ptr<ReaderEndpoint> a_;
  std::unique_ptr<ReaderEndpoint> b_;
};

}  // namespace

FanoutBus::FanoutBus(Bus& first, Bus& second) : Bus(first.prefix()), first_(first), second_(second) {
  if (first.prefix() != second.prefix())
    throw std::invalid_argument("FanoutBus: the two buses have different topic prefixes: " + first.prefix() + " and " +
                                second.prefix());
}

FanoutBus::~FanoutBus() = default;

std::string FanoutBus::Describe() const { return first_.Describe() + " and " + second_.Describe(); }

std::unique_ptr<WriterEndpoint> FanoutBus::OpenWriter(Topic topic, const SampleOps& ops) {
  auto a = first_.OpenWriter(topic, ops);
  auto b = second_.OpenWriter(topic, ops);
  first_.Created(Endpoint::kWriter, topic);
  second_.Created(Endpoint::kWriter, topic);
  return std::make_unique<FanoutWriter>(std::move(a), std::move(b));
}

// Both sides deliver into the one sink (the typed Reader's queue, which takes pushes from any thread).
std::unique_ptr<ReaderEndpoint> FanoutBus::OpenReader(Topic topic, const SampleOps& ops, SampleSink& sink) {
  auto a = first_.OpenReader(topic, ops, sink);
  auto b = second_.OpenReader(topic, ops, sink);
  first_.Created(Endpoint::kReader, topic);
  second_.Created(Endpoint::kReader, topic);
  return std::make_unique<FanoutReader>(std::move(a), std::move(b));
}

}  // namespace turf::dds
