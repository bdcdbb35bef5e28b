// A refused input of the Python kernels: one of turf's named errors
// (core/errors.h) and the reason in words. The module turns it into
// turf.TurfError (a ValueError whose .error is the error's name).
#pragma once

#include <stdexcept>
#include <string>

#include "core/errors.h"

namespace turf::py {

class SimError : public std::invalid_argument {
 public:
  SimError(Error error, const std::string& reason) : std::invalid_argument(reason), error_(error) {}
  Error error() const { return error_; }

 private:
  Error error_;
};

// Throws a SimError for anything but kOk; `what` says which input.
inline void Check(Error error, const std::string& what) {
  if (error != Error::kOk) throw SimError(error, what + ": " + ErrorName(error) + " (" + ErrorMeaning(error) + ")");
}

}  // namespace turf::py
