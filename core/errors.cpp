#include "core/errors.h"

namespace turf {

namespace {

#define TURF_ERROR_NAME(e, name, idl, meaning) name,
constexpr const char* kNames[] = {TURF_ERRORS(TURF_ERROR_NAME)};
#undef TURF_ERROR_NAME
#define TURF_ERROR_MEANING(e, name, idl, meaning) meaning,
constexpr const char* kMeanings[] = {TURF_ERRORS(TURF_ERROR_MEANING)};
#undef TURF_ERROR_MEANING

}  // namespace

const char* ErrorName(Error error) { return error < Error::kCount ? kNames[static_cast<int>(error)] : "?"; }
const char* ErrorMeaning(Error error) { return error < Error::kCount ? kMeanings[static_cast<int>(error)] : "?"; }

std::optional<Error> ErrorFromName(std::string_view name) {
  for (int i = 0; i < static_cast<int>(Error::kCount); ++i)
    if (name == kNames[i]) return static_cast<Error>(i);
  return std::nullopt;
}

}  // namespace turf
