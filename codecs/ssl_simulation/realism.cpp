#include "codecs/ssl_simulation/realism.h"

#include <fmt/format.h>

#include <optional>
#include <utility>

#include "core/realism_fields.h"

namespace turf::simproto {

namespace ws = wire::simulation;

namespace {

bool IsErForce(const std::string& type_url) {
  const std::string name = "RealismConfigErForce";
  return type_url.size() >= name.size() && type_url.compare(type_url.size() - name.size(), name.size(), name) == 0 &&
         (type_url.size() == name.size() || type_url[type_url.size() - name.size() - 1] == '.' ||
          type_url[type_url.size() - name.size() - 1] == '/');
}

// One ER-Force knob: its turf parameter and the factor to SI units. The accepted range is turf-sim's own
// (core/realism_fields.h's table), so nothing the codec passes is refused there: a refusal there came after the
// command's other requests had been applied.
struct Knob {
  const char* name;
  idl::RealismParameter parameter;
  double scale;
  std::optional<double> (*read)(const ws::RealismConfigErForce&);
};

// turf-sim's range of a parameter, in SI units (the table's X-macro: the codec does not link turf_core).
std::pair<double, double> RangeOf(idl::RealismParameter parameter) {
  switch (parameter) {
#define TURF_REALISM_RANGE(e, name, idl_constant, member, unit, min, max, meaning) \
  case idl::idl_constant:                                                          \
    return {min, max};
    TURF_REALISM_FIELDS(TURF_REALISM_RANGE)
#undef TURF_REALISM_RANGE
    default:
      return {0.0, 0.0};
  }
}

// The knob's value in SI units if turf-sim takes it (the check on the converted double, as turf-sim's: a float
// 3.1416 rad is above pi).
bool Accepts(const Knob& knob, double value, Problems* p) {
  const auto [lo, hi] = RangeOf(knob.parameter);
  if (!p->Check(value, lo / knob.scale, hi / knob.scale, fmt::format("realism_config.{}", knob.name))) return false;
  const double si = value * knob.scale;
  if (si >= lo && si <= hi) return true;
  p->Add(DecodeError::kOutOfRange,
         fmt::format("realism_config.{} = {} is outside [{}, {}]", knob.name, value, lo / knob.scale, hi / knob.scale));
  return false;
}

#define TURF_KNOB(knob) \
  [](const ws::RealismConfigErForce& e) { return e.has_##knob() ? std::optional<double>(e.knob()) : std::nullopt; }

const Knob kErForceKnobs[] = {
    {"stddev_ball_p", idl::REALISM_CAMERA_BALL_POSITION_STDDEV, 1.0, TURF_KNOB(stddev_ball_p)},
    {"stddev_robot_p", idl::REALISM_CAMERA_ROBOT_POSITION_STDDEV, 1.0, TURF_KNOB(stddev_robot_p)},
    {"stddev_robot_phi", idl::REALISM_CAMERA_ROBOT_ORIENTATION_STDDEV, 1.0, TURF_KNOB(stddev_robot_phi)},
    {"missing_ball_detections", idl::REALISM_CAMERA_BALL_VANISH, 1.0, TURF_KNOB(missing_ball_detections)},
    {"vision_processing_time", idl::REALISM_CAMERA_PROCESSING_DELAY, 1e-9, TURF_KNOB(vision_processing_time)},
    {"vision_delay", idl::REALISM_CAMERA_LINK_LATENCY, 1e-9, TURF_KNOB(vision_delay)},
    {"robot_command_loss", idl::REALISM_COMMAND_LOSS, 1.0, TURF_KNOB(robot_command_loss)},
    {"enable_invisible_ball", idl::REALISM_CAMERA_BALL_OCCLUSION, 1.0, TURF_KNOB(enable_invisible_ball)},
};

#undef TURF_KNOB

}  // namespace

std::vector<idl::RealismValue> RealismValues(const ws::RealismConfig& config, Problems* p) {
  std::vector<idl::RealismValue> values;
  for (int i = 0; i < config.custom_size(); ++i) {
    const auto& any = config.custom(i);
    if (!IsErForce(any.type_url())) {
      p->AddUnsupported(kUnsupportedRealism, fmt::format("config.realism_config.custom[{}]: {} is not a realism "
                                                         "config turf knows (RealismConfigErForce is)",
                                                         i, any.type_url()));
      continue;
    }
    ws::RealismConfigErForce e;
    if (!e.ParseFromString(any.value())) {
      p->Add(DecodeError::kMalformed, fmt::format("config.realism_config.custom[{}]: not a RealismConfigErForce", i));
      continue;
    }
    for (const Knob& knob : kErForceKnobs) {
      const std::optional<double> v = knob.read(e);
      if (!v || !Accepts(knob, *v, p)) continue;
      idl::RealismValue value;
      value.parameter(knob.parameter);
      value.value(*v * knob.scale);
      values.push_back(value);
    }
    const std::pair<bool, const char*> unsupported[] = {
        {e.has_stddev_ball_area(), "stddev_ball_area"},
        {e.has_ball_visibility_threshold(), "ball_visibility_threshold"},
        {e.has_camera_overlap(), "camera_overlap (set cameras.overlap in the scene)"},
        {e.has_dribbler_ball_detections(), "dribbler_ball_detections"},
        {e.has_camera_position_error(), "camera_position_error"},
        {e.has_robot_response_loss(), "robot_response_loss"},
        {e.has_simulate_dribbling(), "simulate_dribbling (turf always simulates the dribbler)"}};
    for (const auto& [present, name] : unsupported)
      if (present) p->AddUnsupported(kUnsupportedRealism, fmt::format("realism_config.{}: not modelled by turf", name));
  }
  return values;
}

}  // namespace turf::simproto
