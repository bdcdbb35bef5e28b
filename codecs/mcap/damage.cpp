#include "codecs/mcap/damage.h"

#include <utility>

namespace turf::mcap {

const char* ReadErrorName(ReadError error) {
  switch (error) {
#define TURF_MCAP_NAME(e, name, meaning) \
  case ReadError::e:                     \
    return name;
    TURF_MCAP_READ_ERRORS(TURF_MCAP_NAME)
#undef TURF_MCAP_NAME
  }
  return "?";
}

std::string Damage::Describe() const {
  if (ok()) return "ok";
  return std::string(ReadErrorName(error)) + " at offset " + std::to_string(offset) + ": " + message;
}

Damage MakeDamage(ReadError error, uint64_t offset, std::string message) {
  Damage d;
  d.error = error;
  d.offset = offset;
  d.message = std::move(message);
  return d;
}

}  // namespace turf::mcap
