// The CDR bytes of one IDL sample, as Fast DDS writes them on the wire and turf-record stores them.
#pragma once

#include <fastdds/rtps/common/SerializedPayload.h>
#include <gtest/gtest.h>

#include <string>

namespace turf::test {

template <class PubSub, class Sample>
std::string Cdr(const Sample& sample) {
  PubSub type;
  eprosima::fastrtps::rtps::SerializedPayload_t payload(type.getSerializedSizeProvider(const_cast<Sample*>(&sample))());
  EXPECT_TRUE(type.serialize(const_cast<Sample*>(&sample), &payload));
  return std::string(reinterpret_cast<const char*>(payload.data), payload.length);
}

}  // namespace turf::test
