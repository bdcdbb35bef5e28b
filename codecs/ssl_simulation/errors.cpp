#include "codecs/ssl_simulation/errors.h"

#include <google/protobuf/descriptor.h>
#include <google/protobuf/unknown_field_set.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <unordered_map>
#include <vector>

namespace turf::simproto {

namespace pb = google::protobuf;

std::string DecodeErrorCode(DecodeError error) {
  std::string code = "TURF_";
  for (const char* c = DecodeErrorName(error); *c != '\0'; ++c)
    code += static_cast<char>(std::toupper(static_cast<unsigned char>(*c)));
  return code;
}

SimError MakeError(DecodeError error, std::string message) { return {DecodeErrorCode(error), std::move(message)}; }

// `text` cut to at most `max` bytes, not inside a UTF-8 sequence (a protobuf string must stay valid UTF-8).
std::string ClipUtf8(const std::string& text, size_t max) {
  if (text.size() <= max) return text;
  size_t cut = max - 3;
  while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;
  return text.substr(0, cut) + "...";
}

void ToWire(const SimError& error, wire::simulation::SimulatorError* out) {
  out->set_code(error.code);
  out->set_message(ClipUtf8(error.message, kMaxErrorMessage));
}

void AppendErrors(const std::vector<SimError>& errors, pb::RepeatedPtrField<wire::simulation::SimulatorError>* out) {
  const size_t room = kMaxListedErrors - std::min<size_t>(kMaxListedErrors, out->size());
  for (size_t i = 0; i < errors.size() && i < room; ++i) ToWire(errors[i], out->Add());
  if (errors.size() > room)
    ToWire({kMoreErrors, std::to_string(errors.size() - room) + " more errors, not listed"}, out->Add());
}

DecodeError CheckSize(size_t size, std::string* why) {
  if (size == 0) {
    *why = "empty datagram";
    return DecodeError::kEmpty;
  }
  if (size > kMaxDatagramBytes) {
    *why = "datagram of " + std::to_string(size) + " bytes; at most " + std::to_string(kMaxDatagramBytes);
    return DecodeError::kOversized;
  }
  return DecodeError::kOk;
}

DecodeError Parse(const uint8_t* data, size_t size, pb::Message* message, std::string* why) {
  const DecodeError size_error = CheckSize(size, why);
  if (size_error != DecodeError::kOk) return size_error;
  if (!message->ParsePartialFromArray(data, static_cast<int>(size))) {
    *why = "not a " + message->GetTypeName();
    return DecodeError::kMalformed;
  }
  if (!message->IsInitialized()) {
    *why = message->GetTypeName() + " lacks required " + message->InitializationErrorString();
    return DecodeError::kMissingRequired;
  }
  return DecodeError::kOk;
}

namespace {

void CollectUnknown(const pb::Message& message, const std::string& path, std::vector<std::string>* out) {
  const pb::Reflection* reflection = message.GetReflection();
  const pb::UnknownFieldSet& unknown = reflection->GetUnknownFields(message);
  for (int i = 0; i < unknown.field_count(); ++i)
    out->push_back(path + (path.empty() ? "" : ".") + "#" + std::to_string(unknown.field(i).number()));
  std::vector<const pb::FieldDescriptor*> fields;
  reflection->ListFields(message, &fields);
  for (const pb::FieldDescriptor* f : fields) {
    if (f->cpp_type() != pb::FieldDescriptor::CPPTYPE_MESSAGE) continue;
    // google.protobuf.Any payloads are opaque to turf; their own fields are not "unknown".
    if (f->message_type()->full_name() == "google.protobuf.Any") continue;
    const std::string name = path + (path.empty() ? "" : ".") + f->name();
    if (f->is_repeated()) {
      for (int i = 0; i < reflection->FieldSize(message, f); ++i)
        CollectUnknown(reflection->GetRepeatedMessage(message, f, i), name + "[" + std::to_string(i) + "]", out);
    } else {
      CollectUnknown(reflection->GetMessage(message, f), name, out);
    }
  }
}

bool IsAny(const pb::FieldDescriptor* f) { return f->message_type()->full_name() == "google.protobuf.Any"; }

// The message-typed fields of `d` a walk for unknown fields enters (not google.protobuf.Any), found once per
// message type and thread: the walk then looks only at those.
const std::vector<const pb::FieldDescriptor*>& MessageFields(const pb::Descriptor* d) {
  thread_local std::unordered_map<const pb::Descriptor*, std::vector<const pb::FieldDescriptor*>> cache;
  auto [it, added] = cache.try_emplace(d);
  if (added)
    for (int i = 0; i < d->field_count(); ++i)
      if (d->field(i)->cpp_type() == pb::FieldDescriptor::CPPTYPE_MESSAGE && !IsAny(d->field(i)))
        it->second.push_back(d->field(i));
  return it->second;
}

// Pushes the sub-messages of `message` that are present, as ListFields would find them, without ListFields' list
// and sort: a message field is present if repeated (each element) or set. A message with extension ranges takes
// ListFields, which also lists the extensions set.
void PushPresent(const pb::Message& message, std::vector<const pb::Message*>* todo) {
  const pb::Descriptor* d = message.GetDescriptor();
  const pb::Reflection* reflection = message.GetReflection();
  auto push = [&](const pb::FieldDescriptor* f) {
    if (!f->is_repeated()) return todo->push_back(&reflection->GetMessage(message, f));
    for (int i = 0; i < reflection->FieldSize(message, f); ++i)
      todo->push_back(&reflection->GetRepeatedMessage(message, f, i));
  };
  if (d->extension_range_count() > 0) {
    std::vector<const pb::FieldDescriptor*> fields;
    reflection->ListFields(message, &fields);
    for (const pb::FieldDescriptor* f : fields)
      if (f->cpp_type() == pb::FieldDescriptor::CPPTYPE_MESSAGE && !IsAny(f)) push(f);
    return;
  }
  for (const pb::FieldDescriptor* f : MessageFields(d))
    if (f->is_repeated() || reflection->HasField(message, f)) push(f);
}

// CollectUnknown's walk without building paths: unknown fields are rare, and the paths of every nested message
// cost more than the rest of decoding a sync request. Iterative, with one list per thread reused for every call.
bool AnyUnknown(const pb::Message& root) {
  thread_local std::vector<const pb::Message*> todo;
  todo.clear();
  todo.push_back(&root);
  while (!todo.empty()) {
    const pb::Message& message = *todo.back();
    todo.pop_back();
    if (message.GetReflection()->GetUnknownFields(message).field_count() > 0) return true;
    PushPresent(message, &todo);
  }
  return false;
}

}  // namespace

pb::ArenaOptions ArenaOnStack(char* block, size_t size) {
  pb::ArenaOptions options;
  options.initial_block = block;
  options.initial_block_size = size;
  return options;
}

std::vector<std::string> UnknownFields(const pb::Message& message) {
  std::vector<std::string> out;
  if (AnyUnknown(message)) CollectUnknown(message, "", &out);
  return out;
}

void ReportUnknownFields(const pb::Message& message, std::vector<SimError>* errors) {
  const std::vector<std::string> unknown = UnknownFields(message);
  if (unknown.empty()) return;
  std::string list;
  for (size_t i = 0; i < unknown.size() && i < kMaxListedUnknownFields; ++i)
    list += (list.empty() ? "" : ", ") + unknown[i];
  if (unknown.size() > kMaxListedUnknownFields)
    list += " and " + std::to_string(unknown.size() - kMaxListedUnknownFields) + " more";
  errors->push_back({kUnknownField, "fields (or enum values) turf does not know were not applied: " + list});
}

bool Problems::Refuse(double value, double lo, double hi, const std::string& what) {
  if (!std::isfinite(value)) {
    Add(DecodeError::kNotFinite, what + " is not finite");
    return false;
  }
  if (value < lo || value > hi) {
    char buf[160];
    std::snprintf(buf, sizeof(buf), " = %g is outside [%g, %g]", value, lo, hi);
    Add(DecodeError::kOutOfRange, what + buf);
  }
  return false;
}

void Problems::Add(DecodeError error, std::string message) {
  if (error_ == DecodeError::kOk) error_ = error;
  errors_.push_back(MakeError(error, std::move(message)));
}

void Problems::AddUnsupported(const char* code, std::string message) { errors_.push_back({code, std::move(message)}); }

}  // namespace turf::simproto
