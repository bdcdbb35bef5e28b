#include "codecs/hlvs/wire.h"

#include <fmt/format.h>

#include <cmath>

#include "codecs/proto/hlvs.pb.h"
#include "codecs/simspark/framing.h"

namespace turf::hlvs {

namespace {

// Checks one entry's name and numbers; kOk or the refusal with `detail` set.
class Checker {
 public:
  explicit Checker(std::string* detail) : detail_(detail) {}

  bool Name(const std::string& name, const char* list) {
    if (name.size() <= kMaxNameBytes) return true;
    return Fail(Error::kTooLarge, fmt::format("{}: a name of {} bytes", list, name.size()));
  }
  // `allow_infinite`: Webots' velocity control (position = +-infinity).
  bool Number(double v, double max_abs, const std::string& name, const char* what, bool allow_infinite = false) {
    if (std::isnan(v) || (std::isinf(v) && !allow_infinite))
      return Fail(Error::kNotFinite, fmt::format("{} of \"{}\" is {}", what, name, v));
    if (std::isfinite(v) && std::abs(v) > max_abs)
      return Fail(Error::kOutOfRange, fmt::format("{} of \"{}\" is {} (|x| <= {})", what, name, v, max_abs));
    return true;
  }
  bool Gain(double v, const std::string& name) {
    if (!Number(v, kMaxPidGain, name, "PID gain")) return false;
    if (v >= 0) return true;
    return Fail(Error::kOutOfRange, fmt::format("PID gain of \"{}\" is {} (>= 0)", name, v));
  }
  bool Fail(Error e, std::string detail) {
    error = e;
    *detail_ = std::move(detail);
    return false;
  }

  Error error = Error::kOk;

 private:
  std::string* detail_;
};

template <typename Entry>
bool TakeValues(const google::protobuf::RepeatedPtrField<Entry>& in, double (Entry::*get)() const, double max_abs,
                const char* what, bool allow_infinite, Checker* check, std::vector<NamedValue>* out) {
  for (const Entry& e : in) {
    if (!check->Name(e.name(), what)) return false;
    const double v = (e.*get)();
    if (!check->Number(v, max_abs, e.name(), what, allow_infinite)) return false;
    out->push_back({e.name(), v});
  }
  return true;
}

bool TakePids(const pb::ActuatorRequests& r, Checker* check, std::vector<NamedPid>* out) {
  for (const pb::MotorPID& e : r.motor_pids()) {
    if (!check->Name(e.name(), "PID")) return false;
    const Vec3 pid{e.pid().x(), e.pid().y(), e.pid().z()};
    for (double g : {pid.x, pid.y, pid.z})
      if (!check->Gain(g, e.name())) return false;
    out->push_back({e.name(), pid});
  }
  return true;
}

bool TakeSteps(const pb::ActuatorRequests& r, Checker* check, ActuatorRequests* out) {
  for (const pb::SensorTimeStep& e : r.sensor_time_steps()) {
    if (!check->Name(e.name(), "time step")) return false;
    if (e.timestep() > kMaxTimeStepMs)
      return check->Fail(Error::kOutOfRange,
                         fmt::format("time step of \"{}\" is {} ms (<= {})", e.name(), e.timestep(), kMaxTimeStepMs));
    out->sensor_time_steps.push_back({e.name(), e.timestep()});
  }
  for (const pb::CameraQuality& e : r.camera_qualities()) {
    if (!check->Name(e.name(), "camera quality")) return false;
    out->camera_qualities.push_back({e.name(), e.quality()});
  }
  return true;
}

size_t Entries(const pb::ActuatorRequests& r) {
  return static_cast<size_t>(r.motor_positions_size()) + r.motor_velocities_size() + r.motor_forces_size() +
         r.motor_torques_size() + r.motor_pids_size() + r.sensor_time_steps_size() + r.camera_qualities_size() +
         r.camera_exposures_size();
}

void SetVector(const Vec3& v, pb::Vector3* out) {
  out->set_x(v.x);
  out->set_y(v.y);
  out->set_z(v.z);
}

template <typename Out>
void PutVectors(const std::vector<VectorReading>& in, google::protobuf::RepeatedPtrField<Out>* out) {
  for (const VectorReading& r : in) {
    Out* o = out->Add();
    o->set_name(r.name);
    SetVector(r.value, o->mutable_value());
  }
}

template <typename Out>
void PutScalars(const std::vector<ScalarReading>& in, google::protobuf::RepeatedPtrField<Out>* out) {
  for (const ScalarReading& r : in) {
    Out* o = out->Add();
    o->set_name(r.name);
    o->set_value(r.value);
  }
}

}  // namespace

DecodeResult DecodeActuatorRequests(std::string_view payload) {
  DecodeResult result;
  if (payload.size() > kMaxRequestBytes) {
    result.error = Error::kTooLarge;
    result.detail = fmt::format("{} bytes (<= {})", payload.size(), kMaxRequestBytes);
    return result;
  }
  pb::ActuatorRequests r;
  if (!r.ParseFromArray(payload.data(), static_cast<int>(payload.size()))) {
    result.error = Error::kMalformed;
    result.detail = fmt::format("{} bytes that are no ActuatorRequests", payload.size());
    return result;
  }
  if (Entries(r) > kMaxRequestEntries) {
    result.error = Error::kTooMany;
    result.detail = fmt::format("{} entries (<= {})", Entries(r), kMaxRequestEntries);
    return result;
  }
  Checker check(&result.detail);
  ActuatorRequests& out = result.requests;
  const bool ok =
      TakeValues(r.motor_positions(), &pb::MotorPosition::position, kMaxAbsPosition, "position", true, &check,
                 &out.positions) &&
      TakeValues(r.motor_velocities(), &pb::MotorVelocity::velocity, kMaxAbsVelocity, "velocity", false, &check,
                 &out.velocities) &&
      TakeValues(r.motor_forces(), &pb::MotorForce::force, kMaxAbsTorque, "force", false, &check, &out.forces) &&
      TakeValues(r.motor_torques(), &pb::MotorTorque::torque, kMaxAbsTorque, "torque", false, &check, &out.torques) &&
      TakePids(r, &check, &out.pids) && TakeSteps(r, &check, &out) &&
      TakeValues(r.camera_exposures(), &pb::CameraExposure::exposure, 1e9, "exposure", false, &check,
                 &out.camera_exposures);
  if (!ok) {
    result.error = check.error;
    result.requests = {};
  }
  return result;
}

std::string EncodeSensorMeasurements(const SensorMeasurements& m) {
  pb::SensorMeasurements out;
  out.set_time(m.time_ms);
  out.set_real_time(m.real_time_ms);
  for (const TextMessage& t : m.messages) {
    pb::Message* o = out.add_messages();
    o->set_message_type(t.type == MessageType::kError ? pb::Message::ERROR_MESSAGE : pb::Message::WARNING_MESSAGE);
    o->set_text(t.text);
  }
  PutVectors(m.accelerometers, out.mutable_accelerometers());
  for (const BumperReading& b : m.bumpers) {
    pb::BumperMeasurement* o = out.add_bumpers();
    o->set_name(b.name);
    o->set_value(b.value);
  }
  for (const CameraImage& c : m.cameras) {
    pb::CameraMeasurement* o = out.add_cameras();
    o->set_name(c.name);
    o->set_width(c.width);
    o->set_height(c.height);
    o->set_quality(c.quality);
    o->set_image(c.image);
  }
  PutScalars(m.forces, out.mutable_forces());
  PutVectors(m.force3ds, out.mutable_force3ds());
  PutVectors(m.gyros, out.mutable_gyros());
  PutScalars(m.position_sensors, out.mutable_position_sensors());
  std::string bytes;
  out.SerializeToString(&bytes);
  return bytes;
}

EncodeResult FrameSensorMeasurements(const SensorMeasurements& m) {
  const std::string bytes = EncodeSensorMeasurements(m);
  if (bytes.empty()) return {Error::kEmpty, {}};
  if (bytes.size() > kMaxMeasurementBytes) return {Error::kTooLarge, {}};
  return {Error::kOk, Frame(bytes)};
}

std::string Frame(std::string_view payload) { return simspark::Frame(payload); }

}  // namespace turf::hlvs
