#include "participants/replay/resimulate.h"

#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <turf/idl/ClockPubSubTypes.h>
#include <turf/idl/JointsPubSubTypes.h>
#include <turf/idl/SensorStatsPubSubTypes.h>
#include <turf/idl/SimControlPubSubTypes.h>
#include <turf/idl/SimRecordPubSubTypes.h>
#include <turf/idl/SslRobotPubSubTypes.h>
#include <turf/idl/SslVisionPubSubTypes.h>
#include <turf/idl/WorldStatePubSubTypes.h>

#include <algorithm>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <tuple>

#include "dds/memory_bus.h"
#include "loader/legged_scene_yaml.h"
#include "loader/realism_yaml.h"
#include "loader/scene_yaml.h"
#include "participants/common/mcap_file.h"
#include "participants/recorder/sim_time.h"
#include "participants/replay/output_match.h"
#include "participants/sim/applied_inputs.h"
#include "participants/sim/sim_node.h"

namespace turf {
namespace {

// A second of simulation time past the last recorded output: what was sensed before it and published after it
// (camera frames after their processing delay and link) is re-simulated too.
constexpr int64_t kRunPastNs = 1'000'000'000;
// Outputs further apart than this in simulation time are no recording of turf's: turf-sim publishes its clock and
// world state every few ms of simulation time (and nothing while paused, when simulation time stands still). The
// re-simulation ends before such a gap.
constexpr uint64_t kMaxOutputGapNs = 10'000'000'000;

const std::string kRunTopic = dds::Topic::kSimRun.info().suffix;
const std::string kInputsTopic = dds::Topic::kAppliedInputs.info().suffix;

// What a recording holds for a re-simulation.
struct Recording {
  std::optional<idl::SimRun> run;
  std::optional<idl::Clock> start;  // the clock at the run's first frame: its starting time mode
  std::vector<idl::AppliedInputs> inputs;
  OutputMatch outputs;
};

bool Skipped(const ResimulateOptions& o, const std::string& topic) {
  return topic == kRunTopic || std::find(o.skip.begin(), o.skip.end(), topic) != o.skip.end();
}

// The table topic a channel records: its name ends with "/<suffix>" and its schema names the topic's type.
const dds::TopicInfo* TopicOf(const mcap::FileInfo& info, const mcap::Channel& c) {
  const auto schema = info.schemas.find(c.schema_id);
  if (schema == info.schemas.end() || c.message_encoding != "cdr") return nullptr;
  for (const dds::TopicInfo& t : dds::kTopics) {
    const std::string suffix = std::string("/") + t.suffix;
    if (c.topic.size() > suffix.size() && c.topic.compare(c.topic.size() - suffix.size(), suffix.size(), suffix) == 0 &&
        schema->second.name == t.dds_type)
      return &t;
  }
  return nullptr;
}

template <class PubSub>
std::optional<dds::SampleOf<PubSub>> Decode(std::string_view bytes) {
  dds::SampleOf<PubSub> sample;
  if (!FromCdr<PubSub>(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size(), &sample)) return std::nullopt;
  return sample;
}

void Read(const ResimulateOptions& o, Recording* r) {
  const McapFileSource source(o.file);
  if (!source.ok()) throw std::invalid_argument("cannot read " + o.file + ": " + source.error());
  mcap::FileInfo info;
  const mcap::Damage damage = mcap::Scan(source, {}, &info, [&](const mcap::Channel& c, const mcap::Message& m) {
    const dds::TopicInfo* topic = TopicOf(info, c);
    if (topic == nullptr || topic->direction == dds::Direction::kSubscribed) return;
    if (topic->suffix == kRunTopic) {
      if (!r->run) r->run = Decode<idl::SimRunPubSubType>(m.data);
    } else if (topic->suffix == kInputsTopic) {
      if (auto in = Decode<idl::AppliedInputsPubSubType>(m.data)) r->inputs.push_back(std::move(*in));
    } else if (topic->suffix == std::string(dds::Topic::kClock.info().suffix) && !r->start) {
      if (auto clock = Decode<idl::ClockPubSubType>(m.data); clock && clock->frame() == 0) r->start = *clock;
    }
    if (!Skipped(o, topic->suffix)) r->outputs.Recorded(topic->suffix, m.publish_time, std::string(m.data));
  });
  if (damage.error == mcap::ReadError::kBadMagic || damage.error == mcap::ReadError::kNewerVersion)
    throw std::invalid_argument(o.file + ": " + damage.Describe());
  if (!damage.ok()) spdlog::warn("{}: {}; re-simulating what was read before it", o.file, damage.Describe());
}

// The applied-inputs records in sequence order, each once; a gap means the recording lost one.
void CheckInputs(std::vector<idl::AppliedInputs>* inputs) {
  std::stable_sort(inputs->begin(), inputs->end(),
                   [](const idl::AppliedInputs& a, const idl::AppliedInputs& b) { return a.number() < b.number(); });
  inputs->erase(
      std::unique(inputs->begin(), inputs->end(),
                  [](const idl::AppliedInputs& a, const idl::AppliedInputs& b) { return a.number() == b.number(); }),
      inputs->end());
  for (size_t i = 0; i < inputs->size(); ++i) {
    if ((*inputs)[i].number() != i)
      throw std::invalid_argument(fmt::format(
          "applied inputs #{} is not in the recording (it was recorded from a later point, or lost a sample): cannot "
          "re-simulate",
          i));
    if (i > 0 && (*inputs)[i].step() < (*inputs)[i - 1].step())
      throw std::invalid_argument(fmt::format("applied inputs #{} goes back in steps", i));
  }
}

template <class SceneKind>
void ApplyRealism(const idl::SimRun& run, SceneKind* scene) {
  if (run.realism().empty()) return;
  const RealismLoadResult r = LoadRealism(run.realism());
  if (!r.realism) throw std::invalid_argument("the recorded realism '" + run.realism() + "' does not load");
  scene->realism = *r.realism;
}

SceneSource SourceOf(const idl::SimRun& run) {
  return {run.kind(), run.scene_name(), run.scene_path(), run.scene_dir(), run.scene_yaml(), run.realism(), run.seed()};
}

// Serializes what the node publishes on one topic, as turf-record does, into the match.
class Tap {
 public:
  virtual ~Tap() = default;
};

template <class PubSub>
class TypedTap final : public Tap {
 public:
  TypedTap(dds::Bus& bus, const dds::TopicDef<PubSub>& topic, OutputMatch& match)
      : suffix_(topic.info().suffix), match_(match) {
    reader_ = bus.MakeReader(topic, [this] { Drain(); });  // latched samples arrive before it returns: null then
    Drain();
  }

 private:
  void Drain() {
    if (!reader_ || !reader_->Take(&samples_)) return;
    for (const auto& s : samples_) {
      std::vector<uint8_t> cdr;
      if (ToCdr<PubSub>(s, &cdr))
        match_.Resimulated(suffix_, record::SimTimeOf(s), std::string(cdr.begin(), cdr.end()));
    }
  }

  const std::string suffix_;
  OutputMatch& match_;
  std::vector<dds::SampleOf<PubSub>> samples_;
  std::unique_ptr<dds::Reader<PubSub>> reader_;
};

std::vector<std::unique_ptr<Tap>> TapOutputs(const ResimulateOptions& o, dds::Bus& bus, OutputMatch& match) {
  std::vector<std::unique_ptr<Tap>> taps;
  std::apply(
      [&](const auto&... topic) {
        auto add = [&](const auto& t) {
          if (t.info().direction == dds::Direction::kSubscribed || Skipped(o, t.info().suffix)) return;
          taps.push_back(std::make_unique<TypedTap<typename std::decay_t<decltype(t)>::PubSubType>>(bus, t, match));
        };
        (add(topic), ...);
      },
      dds::kTypedTopics);
  return taps;
}

template <class SceneKind>
ResimulateResult Run(const ResimulateOptions& o, SceneKind scene, Recording& r, const std::function<bool()>& stop) {
  ApplyRealism(*r.run, &scene);
  auto schedule = std::make_shared<InputSchedule>(std::move(r.inputs));
  SimNodeOptions options;
  options.name = "turf-replay/resimulate";
  // As the run began: a match started in lockstep (or paused) took its steps from STEP requests, which free-running
  // refuses. Any other mode is never paced here.
  const bool lockstep = r.start && r.start->mode() == idl::TIME_LOCKSTEP;
  options.mode = lockstep ? TimeMode::kLockstep : TimeMode::kFreeRunning;
  options.start_paused = r.start && r.start->paused();
  options.scene_source = SourceOf(*r.run);
  options.resimulate = schedule;
  dds::MemoryBus bus;
  OutputMatch& match = r.outputs;
  const auto taps = TapOutputs(o, bus, match);
  SimNode node(std::move(scene), options, bus);
  const uint64_t contiguous = match.ContiguousEnd(kMaxOutputGapNs);
  if (contiguous < match.last_recorded_time())
    spdlog::warn(
        "recorded outputs at sim times up to {:.3f} s, but none between {:.3f} s and the next ({} s without one): "
        "re-simulating up to the gap",
        static_cast<double>(match.last_recorded_time()) * 1e-9, static_cast<double>(contiguous) * 1e-9,
        kMaxOutputGapNs / 1'000'000'000);
  const int64_t end_ns =
      static_cast<int64_t>(std::min<uint64_t>(contiguous, std::numeric_limits<int64_t>::max() - kRunPastNs)) +
      kRunPastNs;
  // Every applied-inputs record is an output of its own time too: one the run has not reached by `end_ns` names a
  // step no recording reaches.
  node.Run([&] { return stop() || !schedule->error().empty() || node.Stats().sim_time_ns >= end_ns; });

  ResimulateResult result;
  result.recorded = match.recorded();
  result.reproduced = match.reproduced();
  result.unrecorded = match.unrecorded();
  result.input_records = schedule->applied();
  result.sim_time_ns = node.Stats().sim_time_ns;
  if (!schedule->error().empty()) {
    result.verdict = "a recorded input could not be applied: " + schedule->error();
    return result;
  }
  if (!schedule->done()) {
    result.verdict = fmt::format(
        "the re-simulation stopped at step {} (sim time {:.6f} s) with {} of {} applied-inputs records left: {} (step "
        "{})",
        node.Stats().frame, result.sim_time_ns * 1e-9, schedule->size() - schedule->applied(), schedule->size(),
        result.sim_time_ns >= end_ns ? "the next one is past the recording's outputs"
                                     : "the world could not step to the next one",
        schedule->next_step());
    return result;
  }
  const OutputMatch::Difference d = match.FirstDifference();
  if (d.found) {
    result.verdict = d.line;
    result.topic = d.topic;
    result.index = d.index;
    result.diff_sim_time_ns = static_cast<int64_t>(d.sim_time_ns);
    return result;
  }
  result.identical = true;
  result.verdict = fmt::format(
      "identical: {} recorded outputs re-simulated byte for byte from {} applied-inputs records (sim time {:.3f} s; "
      "{} re-simulated samples not in the recording)",
      result.recorded, result.input_records, result.sim_time_ns * 1e-9, result.unrecorded);
  return result;
}

}  // namespace

ResimulateResult Resimulate(const ResimulateOptions& options, const std::function<bool()>& stop) {
  Recording r;
  Read(options, &r);
  if (!r.run) throw std::invalid_argument(options.file + " holds no sim/run sample: it cannot be re-simulated");
  if (r.run->resumed())
    throw std::invalid_argument("the recorded run resumed from a snapshot: it cannot be re-simulated from its scene");
  if (r.run->scene_yaml().empty())
    throw std::invalid_argument("the recording's sim/run has no scene text: it cannot be re-simulated");
  CheckInputs(&r.inputs);
  spdlog::info("re-simulating {}: {} scene '{}' (seed {}, from {}), {} applied-inputs records, {} recorded outputs",
               options.file, r.run->kind(), r.run->scene_name(), r.run->seed(), r.run->scene_path(), r.inputs.size(),
               r.outputs.recorded());
  if (r.run->kind() == "legged") {
    LeggedSceneLoadResult loaded = ParseLeggedSceneYaml(r.run->scene_yaml(), r.run->scene_dir());
    if (!loaded.scene)
      throw std::invalid_argument("the recorded legged scene does not load: " +
                                  (loaded.errors.empty() ? std::string("?") : loaded.errors.front()));
    return Run(options, std::move(*loaded.scene), r, stop);
  }
  if (r.run->kind() != "ssl") throw std::invalid_argument("the recorded scene kind '" + r.run->kind() + "' is unknown");
  SceneLoadResult loaded = ParseSceneYaml(r.run->scene_yaml(), r.run->scene_dir());
  if (!loaded.scene)
    throw std::invalid_argument("the recorded scene does not load: " +
                                (loaded.errors.empty() ? std::string("?") : loaded.errors.front()));
  return Run(options, std::move(*loaded.scene), r, stop);
}

}  // namespace turf
