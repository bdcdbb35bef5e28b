// The HLVS robot API on the wire (shared/protocols/hlvs.md), as pure functions: the 8-byte greeting, the framing
// (4-byte big-endian length, then one protobuf message: the SimSpark framing, codecs/simspark/framing.h), the
// client's ActuatorRequests decoded into plain values with validation, and SensorMeasurements encoded from plain
// values. No sockets, clocks or globals; participants/hlvs_bridge owns the I/O. Messages: codecs/proto/hlvs.proto.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "core/errors.h"

namespace turf::hlvs {

// Sent right after accepting, no length prefix: exactly 8 bytes each (the NUL included).
inline constexpr std::string_view kWelcome{"Welcome\0", 8};
inline constexpr std::string_view kRefused{"Refused\0", 8};

// An ActuatorRequests frame above this is refused (the sample client's requests are tens of bytes; every motor and
// sensor of a robot with names is under 4 KiB).
inline constexpr size_t kMaxRequestBytes = 64 * 1024;
// Entries of one request, all lists together.
inline constexpr size_t kMaxRequestEntries = 1024;
// A device name (the reference's are under 20 characters).
inline constexpr size_t kMaxNameBytes = 64;
// The sample client's limit of a SensorMeasurements frame: above it, or 0, it drops the connection.
inline constexpr size_t kMaxMeasurementBytes = 1920 * 1080 * 3 + 1000;
// Plausibility bounds of request values (beyond them: kOutOfRange).
inline constexpr double kMaxAbsPosition = 1e3;  // rad or m; +-infinity is Webots' velocity control and allowed
inline constexpr double kMaxAbsVelocity = 1e3;  // rad/s
inline constexpr double kMaxAbsTorque = 1e4;    // N.m or N
inline constexpr double kMaxPidGain = 1e6;      // each of P, I, D, and >= 0
inline constexpr uint32_t kMaxTimeStepMs = 3600 * 1000;

struct Vec3 {
  double x = 0, y = 0, z = 0;
};
struct NamedValue {
  std::string name;
  double value = 0;
};
struct NamedPid {
  std::string name;
  Vec3 pid;  // x = P, y = I, z = D
};
struct NamedStep {
  std::string name;
  uint32_t time_step_ms = 0;
};
struct NamedQuality {
  std::string name;
  int32_t quality = 0;
};

// One decoded ActuatorRequests, lists in wire order.
struct ActuatorRequests {
  std::vector<NamedValue> positions;
  std::vector<NamedValue> velocities;
  std::vector<NamedValue> forces;
  std::vector<NamedValue> torques;
  std::vector<NamedPid> pids;
  std::vector<NamedStep> sensor_time_steps;
  std::vector<NamedQuality> camera_qualities;
  std::vector<NamedValue> camera_exposures;
};

// Errors: kTooLarge (above kMaxRequestBytes, or a name above kMaxNameBytes), kMalformed (not an ActuatorRequests),
// kTooMany (above kMaxRequestEntries), kNotFinite (a NaN anywhere, an infinity anywhere but a position),
// kOutOfRange (beyond the bounds above). A refused request is refused whole.
struct DecodeResult {
  Error error = Error::kOk;
  std::string detail;  // what was refused, for the log
  ActuatorRequests requests;
};
DecodeResult DecodeActuatorRequests(std::string_view payload);

enum class MessageType : int { kError = 0, kWarning = 1 };
struct TextMessage {
  MessageType type = MessageType::kWarning;
  std::string text;
};
struct VectorReading {
  std::string name;
  Vec3 value;
};
struct ScalarReading {
  std::string name;
  double value = 0;
};
struct BumperReading {
  std::string name;
  bool value = false;
};
struct CameraImage {
  std::string name;
  uint32_t width = 0, height = 0;
  int32_t quality = -1;  // -1: raw
  std::string image;     // width * height * 3 bytes, B G R, rows from the top
};

// One SensorMeasurements; empty lists are not sent.
struct SensorMeasurements {
  uint32_t time_ms = 0;
  uint64_t real_time_ms = 0;
  std::vector<TextMessage> messages;
  std::vector<VectorReading> accelerometers;
  std::vector<BumperReading> bumpers;
  std::vector<CameraImage> cameras;
  std::vector<ScalarReading> forces;
  std::vector<VectorReading> force3ds;
  std::vector<VectorReading> gyros;
  std::vector<ScalarReading> position_sensors;
};

// The protobuf bytes. proto3 sends no zeros: with time_ms and real_time_ms both 0 and nothing else the message is
// empty, which the client takes for a broken stream (the server's time starts at 8 ms).
std::string EncodeSensorMeasurements(const SensorMeasurements& m);
// The framed message; no bytes and kEmpty for an empty message, kTooLarge above kMaxMeasurementBytes (both of which
// the client would refuse).
struct EncodeResult {
  Error error = Error::kOk;
  std::string framed;
};
EncodeResult FrameSensorMeasurements(const SensorMeasurements& m);

// The framed bytes of a payload (4-byte big-endian length first).
std::string Frame(std::string_view payload);

}  // namespace turf::hlvs
