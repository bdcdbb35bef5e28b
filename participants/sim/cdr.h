// A DDS sample to and from its CDR bytes as they travel on DDS (the generated PubSubType's serialization, with its
// encapsulation header): the form turf-sim's applied-inputs record carries (applied_inputs.h) and turf-record
// writes. Templates over a table topic's PubSubType; they need its generated header.
#pragma once

#include <fastdds/rtps/common/SerializedPayload.h>

#include <cstdint>
#include <cstring>
#include <vector>

#include "dds/topics.h"

namespace turf {

// Samples above this are refused when read back (no topic of turf's comes near it).
inline constexpr size_t kMaxCdrSample = 16u << 20;

// One type object per thread and type: making one computes the type's bounds, which costs more than a small sample.
template <class PubSub>
PubSub& TypeOnThisThread() {
  thread_local PubSub type;
  return type;
}

template <class PubSub>
bool ToCdr(const dds::SampleOf<PubSub>& sample, std::vector<uint8_t>* out) {
  PubSub& type = TypeOnThisThread<PubSub>();
  eprosima::fastrtps::rtps::SerializedPayload_t payload(
      type.getSerializedSizeProvider(const_cast<void*>(static_cast<const void*>(&sample)))());
  if (!type.serialize(const_cast<void*>(static_cast<const void*>(&sample)), &payload)) return false;
  out->assign(payload.data, payload.data + payload.length);
  return true;
}

// False (and `out` unspecified) if the bytes are no CDR sample of the type.
template <class PubSub>
bool FromCdr(const uint8_t* data, size_t size, dds::SampleOf<PubSub>* out) {
  if (size == 0 || size > kMaxCdrSample) return false;
  PubSub& type = TypeOnThisThread<PubSub>();
  eprosima::fastrtps::rtps::SerializedPayload_t payload(static_cast<uint32_t>(size));
  std::memcpy(payload.data, data, size);
  payload.length = static_cast<uint32_t>(size);
  try {
    return type.deserialize(&payload, out);
  } catch (...) {
    return false;
  }
}

}  // namespace turf
