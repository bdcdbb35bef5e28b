#include "codecs/hlvs/session.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace turf::hlvs {

namespace {

constexpr double kMiB = 1024.0 * 1024.0;
constexpr double kTeamBandwidthMb = 350.0;  // MB/s per team, network and rendering alike

double Clamp(double v, double lo, double hi) { return std::min(std::max(v, lo), hi); }

}  // namespace

Session::Session(SessionOptions options) : options_(std::move(options)) {
  motors_.resize(options_.model->motors.size());
  options_.limits.resize(motors_.size());
  options_.team_players = std::max(1, options_.team_players);
}

void Session::Warn(std::string text) {
  if (pending_.size() >= kMaxWarnings) {
    ++unlisted_warnings_;
    return;
  }
  pending_.push_back({MessageType::kWarning, std::move(text)});
}

Session::Motor* Session::FindMotor(const std::string& name, const char* what) {
  const auto& table = options_.model->motors;
  for (size_t i = 0; i < table.size(); ++i)
    if (name == table[i].motor) return &motors_[i];
  Warn(fmt::format("Motor \"{}\" not found, {} command ignored.", name, what));
  return nullptr;
}

void Session::Apply(const ActuatorRequests& r, uint32_t now_ms) {
  for (const NamedValue& p : r.positions) {
    if (Motor* m = FindMotor(p.name, "position")) {
      if (m->torque_control || !m->commanded || m->target != p.value) {
        m->integral = 0;
        m->has_last_error = false;
      }
      m->commanded = true;
      m->torque_control = false;
      m->target = p.value;
    }
  }
  for (const NamedValue& v : r.velocities) {
    if (Motor* m = FindMotor(v.name, "velocity")) {
      m->velocity = std::abs(v.value);
      // A velocity alone: position control holding where the joint is (Webots' target starts there).
      if (!m->commanded) m->target = std::numeric_limits<double>::quiet_NaN();
      m->commanded = true;
    }
  }
  auto set_torque = [&](const NamedValue& t, const char* what) {
    if (Motor* m = FindMotor(t.name, what)) {
      m->commanded = true;
      m->torque_control = true;
      m->torque = t.value;
    }
  };
  for (const NamedValue& f : r.forces) set_torque(f, "force");
  for (const NamedValue& t : r.torques) set_torque(t, "torque");
  for (const NamedPid& p : r.pids) {
    if (Motor* m = FindMotor(p.name, "PID")) m->pid = p.pid;
  }
  for (const NamedQuality& q : r.camera_qualities) {
    if (Classify(q.name) != Device::kCamera) {
      Warn(fmt::format("Camera \"{}\" not found, quality command ignored.", q.name));
    } else {
      Warn("CameraQuality is not yet implemented, ignored.");
    }
  }
  for (const NamedValue& e : r.camera_exposures) {
    if (Classify(e.name) != Device::kCamera) {
      Warn(fmt::format("Camera \"{}\" not found, exposure command ignored.", e.name));
    } else {
      sensors_[e.name].exposure = e.value;
    }
  }
  for (const NamedStep& s : r.sensor_time_steps) SetTimeStep(s, now_ms);
}

Session::Device Session::Classify(const std::string& name) const {
  const RobotModel& model = *options_.model;
  if (name == kAccelerometer) return Device::kAccel;
  if (name == kGyro) return Device::kGyroscope;
  for (const MotorEntry& m : model.motors) {
    if (name == m.motor) return Device::kMotor;
    if (name == PositionSensorName(m)) return Device::kPosition;
  }
  for (const TouchEntry& t : model.touch)
    if (name == t.name) return Device::kTouch;
  for (const CameraEntry& c : model.cameras)
    if (name == c.name) return Device::kCamera;
  return Device::kNone;
}

void Session::SetTimeStep(const NamedStep& s, uint32_t now_ms) {
  const Device device = Classify(s.name);
  if (device == Device::kNone) return Warn(fmt::format("Device \"{}\" not found, time step command, ignored.", s.name));
  if (device == Device::kMotor)
    return Warn(fmt::format("Device \"{}\" is not supported, time step command, ignored.", s.name));
  Sensor& sensor = sensors_[s.name];
  if (s.time_step_ms == 0) {
    sensor.period = 0;
    return;
  }
  const uint32_t minimum = device == Device::kCamera ? kMinCameraStepMs : kBasicStepMs;
  if (s.time_step_ms < minimum)
    return Warn(fmt::format("Time step for \"{}\" should be greater or equal to {}, ignoring {} value.", s.name,
                            minimum, s.time_step_ms));
  if (s.time_step_ms % kBasicStepMs != 0)
    return Warn(fmt::format("Time step for \"{}\" should be a multiple of {}, ignoring {} value.", s.name, kBasicStepMs,
                            s.time_step_ms));
  if (sensor.period == s.time_step_ms) return;  // repeating the current value changes nothing
  if (device == Device::kCamera && !CameraQuotaAllows(s.name, s.time_step_ms)) return;
  sensor.period = s.time_step_ms;
  sensor.next = now_ms + s.time_step_ms;
}

void Session::TellCameras() {
  for (const CameraEntry& c : options_.model->cameras) {
    auto it = sensors_.find(c.name);
    const uint32_t period = it == sensors_.end() ? 0 : it->second.period;
    uint32_t& told = told_[c.name];
    if (period == told) continue;
    told = period;
    if (options_.cameras != nullptr) options_.cameras->Enable(options_.robot, c.mjcf, period);
  }
}

void Session::ClientLeft() {
  sensors_.clear();
  pending_.clear();
  unlisted_warnings_ = 0;
  camera_unavailable_ = false;
  TellCameras();
}

bool Session::CameraQuotaAllows(const std::string& name, uint32_t period) {
  double total = 0;
  for (const CameraEntry& c : options_.model->cameras) {
    uint32_t p = name == c.name ? period : 0;
    if (p == 0) {
      auto it = sensors_.find(c.name);
      if (it != sensors_.end()) p = it->second.period;
    }
    if (p > 0) total += c.width * c.height * 3.0 * 1000.0 / p / kMiB;
  }
  const double limit = kTeamBandwidthMb / options_.team_players;
  if (total <= limit) return true;
  Warn(fmt::format("requested rendering bandwidth is above the limit ({:.0f}MB/s > {:.0f}MB/s)", total, limit));
  return false;
}

bool Session::Due(const std::string& name, uint32_t now_ms) {
  auto it = sensors_.find(name);
  if (it == sensors_.end() || it->second.period == 0 || now_ms < it->second.next) return false;
  Sensor& s = it->second;
  s.next += s.period;
  if (s.next <= now_ms) s.next = now_ms + s.period;  // a gap in the steps: no burst of catching up
  return true;
}

SensorMeasurements Session::Measure(const RobotReading& reading, uint32_t now_ms, uint64_t real_time_ms) {
  SensorMeasurements out;
  out.time_ms = now_ms;
  out.real_time_ms = real_time_ms;
  TellCameras();
  out.messages = std::move(pending_);
  pending_.clear();
  if (unlisted_warnings_ > 0)
    out.messages.push_back({MessageType::kWarning, fmt::format("{} more warnings, not listed.", unlisted_warnings_)});
  unlisted_warnings_ = 0;
  const RobotModel& model = *options_.model;
  for (size_t i = 0; i < model.motors.size() && i < reading.position.size(); ++i) {
    const std::string name = PositionSensorName(model.motors[i]);
    if (Due(name, now_ms)) out.position_sensors.push_back({name, reading.position[i]});
  }
  if (Due(kAccelerometer, now_ms)) out.accelerometers.push_back({kAccelerometer, reading.accelerometer});
  if (Due(kGyro, now_ms)) out.gyros.push_back({kGyro, reading.gyro});
  for (size_t i = 0; i < model.touch.size() && i < reading.touch.size(); ++i) {
    const TouchEntry& t = model.touch[i];
    if (!Due(t.name, now_ms)) continue;
    const RobotReading::Touch& v = reading.touch[i];
    if (t.kind == TouchKind::kForce) out.forces.push_back({t.name, v.force});
    if (t.kind == TouchKind::kForce3d) out.force3ds.push_back({t.name, v.force3d});
    if (t.kind == TouchKind::kBumper) out.bumpers.push_back({t.name, v.contact});
  }
  MeasureCameras(now_ms, &out);
  return out;
}

void Session::MeasureCameras(uint32_t now_ms, SensorMeasurements* out) {
  for (const CameraEntry& c : options_.model->cameras) {
    if (!Due(c.name, now_ms)) continue;
    std::optional<CameraImage> image;
    if (options_.cameras != nullptr)
      image = options_.cameras->Take({options_.robot, c.mjcf, c.width, c.height, sensors_[c.name].exposure, now_ms});
    if (!image || image->width != c.width || image->height != c.height ||
        image->image.size() != size_t{c.width} * c.height * 3) {
      camera_unavailable_ = true;
      continue;
    }
    image->name = c.name;
    image->quality = -1;
    out->cameras.push_back(std::move(*image));
  }
}

std::vector<JointOutput> Session::Commands(const RobotReading& reading) {
  std::vector<JointOutput> out;
  for (size_t i = 0; i < motors_.size(); ++i) {
    if (!motors_[i].commanded || i >= reading.position.size()) continue;
    out.push_back(MotorCommand(i, reading.position[i]));
  }
  return out;
}

JointOutput Session::MotorCommand(size_t i, double position) {
  Motor& m = motors_[i];
  const JointLimits& limits = options_.limits[i];
  JointOutput o{options_.model->motors[i].joint, JointOutput::Mode::kVelocity, 0};
  const double max_velocity = options_.model->max_velocity;
  const double limit = m.velocity < 0 ? max_velocity : std::min(m.velocity, max_velocity);
  if (m.torque_control) {
    o.mode = JointOutput::Mode::kTorque;
    o.value = Clamp(m.torque, -limits.effort, limits.effort);
  } else if (std::isnan(m.target)) {
    m.target = position;  // the first step after a velocity-only command: hold here
    o.value = 0;
  } else if (std::isinf(m.target)) {
    o.value = std::copysign(limit, m.target);  // Webots' velocity control
  } else {
    const double dt = kBasicStepMs * 1e-3;
    const double error = Clamp(m.target, limits.lo, limits.hi) - position;
    m.integral += error * dt;
    const double derivative = m.has_last_error ? (error - m.last_error) / dt : 0.0;
    m.last_error = error;
    m.has_last_error = true;
    o.value = Clamp(m.pid.x * error + m.pid.y * m.integral + m.pid.z * derivative, -limit, limit);
  }
  // A reading that is no number (a forged robots/state sample) holds the joint: turf-sim refuses a step's commands
  // whole, so one NaN would have cost every robot its commands for that step.
  if (!std::isfinite(o.value)) {
    o.value = 0;
    m.integral = 0;
    m.has_last_error = false;
  }
  return o;
}

std::map<std::string, uint32_t> Session::SensorPeriods() const {
  std::map<std::string, uint32_t> out;
  for (const auto& [name, s] : sensors_)
    if (s.period > 0) out[name] = s.period;
  return out;
}

NetworkQuota::NetworkQuota(int team_players) : quota_mb_(kTeamBandwidthMb / std::max(1, team_players)) {}

bool NetworkQuota::Admit(size_t bytes, uint64_t now_ms) {
  while (!sent_.empty() && sent_.front().first + 1000 <= now_ms) {
    total_ -= sent_.front().second;
    sent_.pop_front();
  }
  if (static_cast<double>(total_ + bytes) > quota_mb_ * kMiB) return false;
  sent_.emplace_back(now_ms, bytes);
  total_ += bytes;
  return true;
}

std::string NetworkQuota::ExceededText() const { return fmt::format("{:.6f} MB/s quota exceeded.", quota_mb_); }

}  // namespace turf::hlvs
