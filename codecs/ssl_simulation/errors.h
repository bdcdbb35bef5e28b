// Named errors of the SSL simulation protocol codec, and the small helpers the
// decoders share: datagram checks, parsing with required-field checks, unknown
// field detection, and a collector of value problems.
//
// Two kinds of problem, kept apart:
//  - fatal (a DecodeError other than kOk): the datagram is refused as a whole;
//    nothing of it reaches turf-sim, no robot moves. The SimulatorErrors say why.
//  - not supported (a SimulatorError whose code starts TURF_UNSUPPORTED_ or is
//    TURF_UNKNOWN_FIELD): that part is not applied, the rest is, and the answer
//    names what was left out. Nothing is ignored silently.
#pragma once

#include <google/protobuf/arena.h>
#include <google/protobuf/message.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "codecs/proto/ssl_simulation.pb.h"
#include "core/errors.h"

namespace turf::simproto {

// The codec's refusals are turf's one taxonomy (core/errors.h): kEmpty, kOversized,
// kMalformed, kMissingRequired, kNotFinite, kOutOfRange, kOutsideField,
// kUnknownRobot (id > 15, id >= robots_per_team, or no team), kDuplicateRobot.
// Names: "empty", "malformed", ... (snake_case, as turf's other refusal kinds).
using DecodeError = turf::Error;
inline const char* DecodeErrorName(DecodeError error) { return turf::ErrorName(error); }
// The SimulatorError code for a fatal error: "TURF_" + upper-case name.
std::string DecodeErrorCode(DecodeError error);

// Larger datagrams are refused unread. A full SimulatorCommand with geometry
// is ~3 KB; a RobotControl for 16 robots well under 1 KB.
inline constexpr size_t kMaxDatagramBytes = 16384;

// Codes for what turf understands but does not do.
inline constexpr char kUnsupportedGeometry[] = "TURF_UNSUPPORTED_CONFIG_GEOMETRY";
inline constexpr char kUnsupportedRobotSpecs[] = "TURF_UNSUPPORTED_CONFIG_ROBOT_SPECS";
inline constexpr char kUnsupportedRealism[] = "TURF_UNSUPPORTED_CONFIG_REALISM";
inline constexpr char kUnsupportedVisionPort[] = "TURF_UNSUPPORTED_CONFIG_VISION_PORT";
inline constexpr char kUnsupportedByForce[] = "TURF_UNSUPPORTED_BY_FORCE";
inline constexpr char kUnsupportedSyncSpeed[] = "TURF_UNSUPPORTED_SPEED_IN_SYNC_MODE";
inline constexpr char kUnknownField[] = "TURF_UNKNOWN_FIELD";
// Codes the bridge adds: turf-sim refused a request (the message gives its
// reason), did not answer in time, or has not been seen yet.
inline constexpr char kRejectedBySim[] = "TURF_REJECTED_BY_SIM";
inline constexpr char kNoReply[] = "TURF_NO_REPLY";
inline constexpr char kSimNotAvailable[] = "TURF_SIM_NOT_AVAILABLE";
// A sync request while synchronous mode is off: whoever starts the match enables it (it stops vision for all).
inline constexpr char kSyncDisabled[] = "TURF_SYNC_DISABLED";
// The sender's address is not on the port's source allowlist (--blue-allow, --yellow-allow, --operator-allow).
inline constexpr char kNotAllowed[] = "TURF_NOT_ALLOWED";
// A response lists at most kMaxListedErrors errors, each message at most kMaxErrorMessage bytes, then this one
// ("N more errors, not listed"): a datagram of 3.6 KB was answered with 65 KB (an amplifier), or not at all.
inline constexpr char kMoreErrors[] = "TURF_MORE_ERRORS";
inline constexpr size_t kMaxListedErrors = 16;
inline constexpr size_t kMaxErrorMessage = 512;
inline constexpr size_t kMaxListedUnknownFields = 16;

struct SimError {
  std::string code;
  std::string message;
  bool operator==(const SimError& o) const { return code == o.code && message == o.message; }
};

SimError MakeError(DecodeError error, std::string message);
void ToWire(const SimError& error, wire::simulation::SimulatorError* out);
void AppendErrors(const std::vector<SimError>& errors,
                  google::protobuf::RepeatedPtrField<wire::simulation::SimulatorError>* out);

// Empty or oversized: the datagram is refused before parsing.
DecodeError CheckSize(size_t size, std::string* why);

// Parses `message` from bytes: kMalformed if the bytes are not one, kMissingRequired
// (naming the fields) if a required field is absent.
DecodeError Parse(const uint8_t* data, size_t size, google::protobuf::Message* message, std::string* why);

// Arena options whose first block is `block` (the caller's, e.g. on its stack); more blocks come from the heap.
constexpr size_t kArenaBlockBytes = 16 * 1024;
google::protobuf::ArenaOptions ArenaOnStack(char* block, size_t size);

// Parses a `Message` and converts it with `convert(message)`; a datagram that
// does not parse gives a `Decode` with only the error (and its SimError).
// The message lives on an arena whose first block is on the stack: a sync request's dozens of nested messages cost
// no heap allocation each (they showed in the sync port's profile).
template <class Message, class Decode, class Convert>
Decode ParseThen(const uint8_t* data, size_t size, Convert convert) {
  alignas(16) char block[kArenaBlockBytes];
  google::protobuf::Arena arena(ArenaOnStack(block, sizeof block));
  Message& message = *google::protobuf::Arena::CreateMessage<Message>(&arena);
  std::string why;
  const DecodeError error = Parse(data, size, &message, &why);
  if (error == DecodeError::kOk) return convert(message);
  Decode out;
  out.error = error;
  out.errors.push_back(MakeError(error, why));
  return out;
}

// Paths of fields the parser did not know (e.g. "control.teleport_ball.#12"),
// anywhere in the message; an unknown enum value of a proto2 field lands here too.
std::vector<std::string> UnknownFields(const google::protobuf::Message& message);
// One TURF_UNKNOWN_FIELD error naming them, or none.
void ReportUnknownFields(const google::protobuf::Message& message, std::vector<SimError>* errors);

// Collects value problems. The first fatal one decides the datagram's error;
// all are reported.
class Problems {
 public:
  // False (and recorded) if `value` is not finite or outside [lo, hi]. The value's name is the parts of `what`
  // joined, built only for a refusal (a sync request checks dozens of values).
  template <class... Parts>
  bool Check(double value, double lo, double hi, const Parts&... what) {
    if (std::isfinite(value) && value >= lo && value <= hi) return true;
    std::string name;
    (name.append(what), ...);
    return Refuse(value, lo, hi, name);
  }
  void Add(DecodeError error, std::string message);
  void AddUnsupported(const char* code, std::string message);
  DecodeError error() const { return error_; }
  bool ok() const { return error_ == DecodeError::kOk; }
  std::vector<SimError>& errors() { return errors_; }

 private:
  bool Refuse(double value, double lo, double hi, const std::string& what);

  DecodeError error_ = DecodeError::kOk;
  std::vector<SimError> errors_;
};

}  // namespace turf::simproto
