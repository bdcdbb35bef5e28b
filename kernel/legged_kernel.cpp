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

// The stream's fields of a sample (legged_kernel.h says which), in one order
// for saving and restoring: `io` is a SampleWriter (State: const) or a
// SampleReader, whose robot_state already has the robot's structure.
template <class State, class Io>
void SampleFields(LeggedStream stream, State& r, Io& io) {
  switch (stream) {
    case LeggedStream::kJoints:
      io.Joints(r.joint_positions, r.joint_names.size());
      io.Joints(r.joint_velocities, r.joint_names.size());
      io.Joints(r.joint_efforts, r.joint_names.size());
      break;
    case LeggedStream::kImu:
      io.Array(r.orientation);
      io.Array(r.gyro);
      io.Array(r.accelerometer);
      io.Array(r.base_position);
      io.Array(r.base_orientation);
      io.Array(r.base_velocity);
      break;
    default:
      for (auto& f : r.forces) {
        io.Values(f.values);
        io.Flag(f.contact);
        io.Array(f.force);
        io.Array(f.point);
      }
      break;
  }
}

struct SampleWriter {
  StateWriter& out;
  void Joints(const std::vector<double>& v, size_t) { out.Doubles(v); }
  void Values(const std::vector<double>& v) { out.Doubles(v); }
  void Flag(bool b) { out.Put(b); }
  template <size_t N>
  void Array(const std::array<double, N>& a) {
    for (double v : a) out.Put(v);
  }
};

struct SampleReader {
  StateReader& in;
  void Joints(std::vector<double>& v, size_t n) { in.Doubles(&v, n); }
  void Values(std::vector<double>& v) {
    v.resize(in.Count(kMaxValues));
    in.Bytes(v.data(), v.size() * sizeof(double));
  }
  void Flag(bool& b) { b = in.Bool(); }
  template <size_t N>
  void Array(std::array<double, N>& a) {
    for (double& v : a) v = in.Get<double>();
  }
};

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
    : world_(std::move(scene)), sensors_(world_.scene().seed, RobotNames(world_.scene())) {
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

void LeggedKernel::SaveTo(StateWriter& out) const {
  world_.Save(out);
  SaveRealism(realism_, out);
  out.Tag(StateTag("LSTR"));
  for (const Stream& s : streams_) {
    s.link.Save(out);
    s.stats.Save(out);
  }
  out.Put<uint64_t>(in_flight_.size());
  for (const InFlight& f : in_flight_) {
    out.Put(f.arrival_ns);
    out.Put(f.sample.stream);
    out.Put(f.sample.robot);
    out.Put(f.sample.time_ns);
    out.Put(f.sample.frame);
    SampleWriter writer{out};
    SampleFields(f.sample.stream, f.sample.robot_state, writer);
  }
  stats_.Save(out);
}

void LeggedKernel::RestoreFrom(StateReader& in) {
  world_.Restore(in);
  realism_ = RestoreRealism(in);
  in.Tag(StateTag("LSTR"));
  for (Stream& s : streams_) {
    s.link.Restore(in);
    s.stats.Restore(in);
  }
  world_.State(&scratch_);  // each robot's structure, for the samples
  in_flight_.resize(in.Count(kMaxInFlight));
  for (InFlight& f : in_flight_) {
    f.arrival_ns = in.Get<int64_t>();
    f.sample.stream = in.Enum(LeggedStream::kCount);
    f.sample.robot = in.Get<int>();
    f.sample.time_ns = in.Get<int64_t>();
    f.sample.frame = in.Get<uint64_t>();
    if (f.sample.robot < 0 || f.sample.robot >= world_.RobotCount()) {
      in.Fail("sample of an unknown robot");
      return;
    }
    f.sample.robot_state = StreamFields(scratch_.robots[f.sample.robot], f.sample.stream);
    SampleReader reader{in};
    SampleFields(f.sample.stream, f.sample.robot_state, reader);
  }
  stats_.Restore(in);
  released_.clear();
}

}  // namespace turf
