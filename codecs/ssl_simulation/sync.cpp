#include "codecs/ssl_simulation/sync.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "codecs/ssl_simulation/step_planner.h"
#include "codecs/ssl_vision/detection.h"
#include "codecs/ssl_vision/timestamps.h"

namespace turf::simproto {

namespace pb = google::protobuf;

namespace ws = wire::simulation;

namespace {

// The requested step in nanoseconds, or why there is none. How many physics
// steps that is depends on the session's carry (StepPlanner), not on the datagram.
void CheckSimStep(const ws::SimulationSyncRequest& in, double step_s, Problems* p, int64_t* sim_step_ns) {
  if (!in.has_sim_step()) return p->Add(DecodeError::kMissingRequired, "sim_step is absent");
  const double sim_step = in.sim_step();
  if (!p->Check(sim_step, 0.0, kMaxSyncStep, "sim_step (s)")) return;
  if (!(sim_step > 0.0)) return p->Add(DecodeError::kOutOfRange, "sim_step must be positive, not 0");
  if (!(step_s > 0.0)) return p->Add(DecodeError::kMissingRequired, "turf-sim's physics step is not known yet");
  *sim_step_ns = FloatSecondsToNanoseconds(in.sim_step());
}

// A request that parsed.
SyncDecode ConvertSyncRequest(const ws::SimulationSyncRequest& message, const ControlContext& context, double step_s) {
  SyncDecode out;
  Problems p;
  CheckSimStep(message, step_s, &p, &out.sim_step_ns);
  ControlContext sync_context = context;
  sync_context.sync = true;
  out.command = ConvertSimulatorCommand(message.simulator_command(), sync_context);
  const int per_team = context.field != nullptr ? context.field->robots_per_team() : 0;
  out.robots = ConvertRobotControl(message.robot_control(), Port::kSync, per_team);
  // Unknown fields inside the parts were reported by their own converters; the rest are the top message's own
  // (sim_step is a scalar). A copy without the parts only when there are some.
  if (message.GetReflection()->GetUnknownFields(message).field_count() > 0) {
    ws::SimulationSyncRequest top = message;
    top.clear_simulator_command();
    top.clear_robot_control();
    ReportUnknownFields(top, &p.errors());
  }

  out.errors = std::move(p.errors());
  out.errors.insert(out.errors.end(), out.command.errors.begin(), out.command.errors.end());
  out.errors.insert(out.errors.end(), out.robots.errors.begin(), out.robots.errors.end());
  for (DecodeError e : {p.error(), out.command.error, out.robots.error}) {
    if (out.error == DecodeError::kOk) out.error = e;
  }
  if (out.error != DecodeError::kOk) {
    out.sim_step_ns = 0;
    out.command.requests.clear();
    out.robots.commands.clear();
    out.robots.wire_ids.clear();
  }
  return out;
}

}  // namespace

// On ParseThen's stack arena, as the team and control ports: the request's dozens of nested messages cost no heap
// allocation each.
SyncDecode DecodeSyncRequest(const uint8_t* data, size_t size, const ControlContext& context, double step_s) {
  return ParseThen<ws::SimulationSyncRequest, SyncDecode>(data, size, [&](const ws::SimulationSyncRequest& message) {
    return ConvertSyncRequest(message, context, step_s);
  });
}

SyncFrames::SyncFrames(const std::vector<idl::CameraFrame>& frames) {
  refs.reserve(frames.size());
  for (const idl::CameraFrame& f : frames) refs.push_back(&f);
}

SyncFrames::SyncFrames(const std::vector<std::shared_ptr<const idl::CameraFrame>>& frames) {
  refs.reserve(frames.size());
  for (const auto& f : frames) refs.push_back(f.get());
}

void FillSyncResponse(const SyncFrames& frames, const idl::SslField& field, const SyncDecode& request,
                      const ContactMap& contacts, const std::vector<SimError>& extra, ws::SimulationSyncResponse* out) {
  std::vector<const idl::CameraFrame*> sorted = frames.refs;
  std::sort(sorted.begin(), sorted.end(), [](const idl::CameraFrame* a, const idl::CameraFrame* b) {
    return a->capture_time_ns() != b->capture_time_ns() ? a->capture_time_ns() < b->capture_time_ns()
                                                        : a->camera_id() < b->camera_id();
  });
  RobotControlDecode answered;  // the commanded robots, with every error of the request
  answered.commands = request.robots.commands;
  answered.wire_ids = request.robots.wire_ids;
  answered.errors = request.errors;
  const vision::WireClock clock(vision::ClockMode::kSim);
  for (const idl::CameraFrame* f : sorted) {
    vision::FrameTimes times{};
    vision::VisionError e = vision::CheckCameraFrame(*f);
    if (e == vision::VisionError::kOk) e = clock.ForFrame(f->capture_time_ns(), f->sent_time_ns(), 0.0, &times);
    if (e != vision::VisionError::kOk) {
      answered.errors.push_back({"TURF_BAD_CAMERA_FRAME", "camera " + std::to_string(f->camera_id()) + " frame " +
                                                              std::to_string(f->frame_number()) +
                                                              " left out: " + vision::VisionErrorName(e)});
      continue;
    }
    vision::FillDetectionFrame(*f, times, vision::FindCamera(field, f->camera_id()), out->add_detection());
  }
  FillRobotControlResponse(answered, contacts, extra, out->mutable_robot_control_response());
}

std::vector<uint8_t> EncodeSyncResponse(const SyncFrames& frames, const idl::SslField& field, const SyncDecode& request,
                                        const ContactMap& contacts, const std::vector<SimError>& extra) {
  alignas(16) char block[kArenaBlockBytes];  // as ParseThen: no heap allocation per detection
  pb::Arena arena(ArenaOnStack(block, sizeof block));
  ws::SimulationSyncResponse& response = *pb::Arena::CreateMessage<ws::SimulationSyncResponse>(&arena);
  FillSyncResponse(frames, field, request, contacts, extra, &response);
  size_t size = response.ByteSizeLong();  // also caches every nested message's size for the serialisation below
  if (size > kMaxResponseBytes) {
    // Leave out the oldest detections; the error itself needs room too.
    int dropped = 0;
    auto* detections = response.mutable_detection();
    while (!detections->empty() && response.ByteSizeLong() + 200 > kMaxResponseBytes) {
      detections->erase(detections->begin());
      ++dropped;
    }
    ToWire({kSyncResponseTooLarge, std::to_string(dropped) + " oldest detection frames left out: the response must "
                                                             "fit one UDP datagram (use a shorter sim_step)"},
           response.mutable_robot_control_response()->add_errors());
    size = response.ByteSizeLong();
  }
  // One pass over the detections for the sizes above, one to write (SerializeToArray would size them again).
  std::vector<uint8_t> bytes(size);
  response.SerializeWithCachedSizesToArray(bytes.data());
  return bytes;
}

}  // namespace turf::simproto
