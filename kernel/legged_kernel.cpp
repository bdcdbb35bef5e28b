#include "kernel/legged_kernel.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <vector>

#include <fmt/format.h>

#include "core/state_fields.h"

namespace turf {

namespace {

constexpr size_t kMaxInFlight = 1 << 16;
constexpr size_t kMaxValues = 1 << 12;

std::vector<std::string> RobotNames(const LeggedScene& s) {
  std::vector<std::string> names;
  for (const LeggedRobot& r : s.robots) names.push_back(r.name);
  return names;
}

const LinkParams& LinkOf(const SensorRealism& r, LeggedStream s) {
  const LinkParams* links[] = {&r.encoder.link, &r.imu.link, &r.touch.link};
  return *links[static_cast<int>(s)];
}

std::string StreamName(const LeggedScene& scene, int robot, LeggedStream s) {
  return "legged/" + scene.robots[robot].name + "/" + LeggedStreamName(s);
}

// The stream's fields of a sample (legged_kernel.h says which), listed once
// (core/state_io.h); restored into a robot_state that already has the robot's
// structure.
template <class Io, class State>
void SampleFields(Io& io, LeggedStream stream, State& r) {
  const size_t joints = r.joint_names.size();
  switch (stream) {
    case LeggedStream::kJoints:
      io(Exactly(r.joint_positions, joints), Exactly(r.joint_velocities, joints), Exactly(r.joint_efforts, joints));
      break;
    case LeggedStream::kImu:
      io(r.orientation, r.gyro, r.accelerometer, r.base_position, r.base_orientation, r.base_velocity);
      break;
    default:
      for (auto& f : r.forces) io(Sized(f.values, kMaxValues), f.contact, f.force, f.point);
      break;
  }
}

// The sample of one stream: the robot's name, id and has_imu and that stream's fields, nothing else (the joint
// stream carries no links, the IMU no joints): three whole copies of every robot at every frame cost more than the
// physics step's serving budget in a 22-robot match.
LeggedRobotState StreamFields(const LeggedRobotState& r, LeggedStream stream) {
  LeggedRobotState out;
  out.name = r.name;
  out.id = r.id;
  out.has_imu = r.has_imu;
  switch (stream) {
    case LeggedStream::kJoints:
      out.joint_names = r.joint_names;
      out.joint_positions = r.joint_positions;
      out.joint_velocities = r.joint_velocities;
      out.joint_efforts = r.joint_efforts;
      break;
    case LeggedStream::kImu:
      out.orientation = r.orientation;
      out.gyro = r.gyro;
      out.accelerometer = r.accelerometer;
      out.base_position = r.base_position;
      out.base_orientation = r.base_orientation;
      out.base_velocity = r.base_velocity;
      break;
    default:
      out.forces = r.forces;
      break;
  }
  return out;
}

}  // namespace

const char* LeggedStreamName(LeggedStream stream) {
  constexpr const char* kNames[] = {"joint_state", "imu", "force"};
  static_assert(std::size(kNames) == static_cast<size_t>(LeggedStream::kCount));
  return stream < LeggedStream::kCount ? kNames[static_cast<int>(stream)] : "?";
}

LeggedKernel::LeggedKernel(LeggedScene scene)
    : world_(std::move(scene)), sensor_seed_(world_.scene().seed), sensors_(sensor_seed_, RobotNames(world_.scene())) {
  const LeggedScene& s = world_.scene();
  sensor_every_ = std::max<int64_t>(1, std::llround(1.0 / (s.rates.joint_state_hz * s.physics.step)));
  for (int r = 0; r < world_.RobotCount(); ++r) {
    for (int k = 0; k < kStreamsPerRobot; ++k) streams_.push_back({Link(LinkParams{}, 0), {}});
  }
  realism_ = s.realism;
  Reset();
}

JointCommandError LeggedKernel::SetJointCommands(int robot, const std::vector<JointCommand>& commands) {
  const JointCommandError e = world_.CheckJointCommands(robot, commands);
  if (e != JointCommandError::kOk) return e;
  for (const JointCommand& c : commands) world_.SetJointCommand(robot, c);
  return JointCommandError::kOk;
}

Error LeggedKernel::PlaceRobot(int robot, const RobotPlacement& p) {
  for (double v : p.position) {
    if (std::abs(v) > kMaxLeggedPlacement) return Error::kOutOfRange;
  }
  return world_.PlaceRobot(robot, p);
}

Error LeggedKernel::PlaceBall(const std::array<double, 3>& position, const std::array<double, 3>& velocity) {
  for (int k = 0; k < 3; ++k) {
    if (std::abs(position[k]) > kMaxLeggedPlacement || std::abs(velocity[k]) > kMaxLeggedBallSpeed)
      return Error::kOutOfRange;
  }
  return world_.PlaceBall(position, velocity);
}

std::string LeggedKernel::SetRealism(const SensorRealism& realism) {
  if (const char* e = CheckRealism(realism); *e != '\0') return e;
  realism_ = realism;
  for (int r = 0; r < world_.RobotCount(); ++r) {
    for (int k = 0; k < kStreamsPerRobot; ++k) {
      const auto s = static_cast<LeggedStream>(k);
      StreamOf(r, s).link.SetParams(LinkOf(realism_, s));
    }
  }
  return "";
}

void LeggedKernel::Reset() {
  world_.Reset();
  if (sensor_seed_ != scene().seed) {  // after a snapshot of another seed: the scene's noise again
    sensor_seed_ = scene().seed;
    sensors_ = LeggedSensors(sensor_seed_, RobotNames(scene()));
  }
  for (int r = 0; r < world_.RobotCount(); ++r) {
    for (int k = 0; k < kStreamsPerRobot; ++k) {
      const auto s = static_cast<LeggedStream>(k);
      Stream& stream = StreamOf(r, s);
      stream.link = Link(LinkOf(realism_, s), StreamSeed(scene().seed, StreamName(scene(), r, s) + "/link"));
      stream.stats = StreamStats{};
    }
  }
  in_flight_.clear();
  stats_.Reset();
  released_.clear();
  SendSensorFrame();
  Release();
}

void LeggedKernel::Step() {
  world_.Step();
  released_.clear();
  if (frame() % sensor_every_ == 0) SendSensorFrame();
  Release();
  CollectStats();
}

void LeggedKernel::Measure(LeggedWorldState* out) const {
  world_.State(out);
  sensors_.Apply(realism_, out);
}

// Every robot's readings of this frame enter their streams' links.
void LeggedKernel::SendSensorFrame() {
  Measure(&scratch_);
  for (int r = 0; r < world_.RobotCount(); ++r) {
    for (int k = 0; k < kStreamsPerRobot; ++k) {
      const auto s = static_cast<LeggedStream>(k);
      Stream& stream = StreamOf(r, s);
      stream.stats.Sent();
      const std::optional<int64_t> arrival = stream.link.Transmit(time_ns());
      if (!arrival) {
        stream.stats.Lost();
        continue;
      }
      if (in_flight_.size() >= kMaxInFlight) in_flight_.pop_front();
      in_flight_.push_back({*arrival, {s, r, time_ns(), frame(), StreamFields(scratch_.robots[r], s)}});
    }
  }
}

// Samples whose delay has passed, in the order they were sent.
void LeggedKernel::Release() {
  auto due = [this](const InFlight& f) { return f.arrival_ns <= time_ns(); };
  for (InFlight& f : in_flight_) {
    if (!due(f)) continue;
    StreamOf(f.sample.robot, f.sample.stream).stats.Delivered((time_ns() - f.sample.time_ns) * 1e-9);
    released_.push_back(std::move(f.sample));
  }
  in_flight_.erase(std::remove_if(in_flight_.begin(), in_flight_.end(), due), in_flight_.end());
}

void LeggedKernel::CollectStats() {
  stats_.Collect(time_ns(), [this](StreamReport& report) {
    for (int r = 0; r < world_.RobotCount(); ++r) {
      for (int k = 0; k < kStreamsPerRobot; ++k) {
        const auto s = static_cast<LeggedStream>(k);
        report.streams.emplace_back(StreamName(scene(), r, s), StreamOf(r, s).stats.Take());
      }
    }
  });
}

// The sections before the samples in flight, listed once (core/state_io.h).
template <class Io, class Self>
void LeggedKernel::Fields(Io& io, Self& self) {
  io(self.world_, self.realism_, self.sensor_seed_);
  io.Tag(StateTag("LSTR"));
  for (auto& s : self.streams_) io(s.link, s.stats);
}

void LeggedKernel::SaveTo(StateWriter& out) const {
  Fields(out, *this);
  out.Put<uint64_t>(in_flight_.size());
  for (const InFlight& f : in_flight_) {
    out(f.arrival_ns, f.sample.stream, f.sample.robot, f.sample.time_ns, f.sample.frame);
    SampleFields(out, f.sample.stream, f.sample.robot_state);
  }
  out(stats_);
}

void LeggedKernel::RestoreFrom(StateReader& in) {
  Fields(in, *this);
  // The snapshot's noise goes on: restored into a kernel of another seed, the readings were that seed's (ground
  // truth equal, the gyro and encoders not).
  sensors_ = LeggedSensors(sensor_seed_, RobotNames(scene()));
  world_.State(&scratch_);  // each robot's structure, for the samples
  in_flight_.resize(in.Count(kMaxInFlight));
  for (InFlight& f : in_flight_) {
    in(f.arrival_ns, InRange(f.sample.stream, LeggedStream::kCount), f.sample.robot, f.sample.time_ns, f.sample.frame);
    if (f.sample.robot < 0 || f.sample.robot >= world_.RobotCount()) {
      in.Fail("sample of an unknown robot");
      return;
    }
    f.sample.robot_state = StreamFields(scratch_.robots[f.sample.robot], f.sample.stream);
    SampleFields(in, f.sample.stream, f.sample.robot_state);
  }
  in(stats_);
  released_.clear();
}

}  // namespace turf
