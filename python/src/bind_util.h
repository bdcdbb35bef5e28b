// Helpers of the module's bindings: NumPy views and copies of C++ buffers,
// team names, the realism as a dict.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <string>
#include <vector>

#include "core/scene.h"
#include "core/sensor_realism.h"

namespace turf::py {

namespace pyb = pybind11;

// A read-only view of `rows` x `columns` doubles owned by `owner` (kept alive by the view).
pyb::array_t<double> View(const double* data, pyb::ssize_t rows, pyb::ssize_t columns, pyb::handle owner);
pyb::array_t<double> View(const double* data, pyb::ssize_t size, pyb::handle owner);
// A copy as rows x columns (rows = size / columns).
pyb::array_t<double> Copy(const std::vector<double>& values, pyb::ssize_t columns);
pyb::array_t<double> Copy(const double* data, pyb::ssize_t size);

// "blue"/"yellow" or 0/1; throws SimError (unknown_team).
Team TeamOf(const pyb::object& team);

// step()'s n: an int (else SimError malformed); one past int's range becomes 0, which step() refuses (out_of_range).
int64_t StepCountOf(const pyb::handle& n);

// A Python int as an int; `outside` for one past int's range (2**70), which the caller then refuses as it would
// any other out-of-range value.
int IntOr(const pyb::handle& value, int outside);

// A C-contiguous float64 array of exactly `shape` from any array-like; throws SimError (malformed) naming `what`
// and the shape expected.
pyb::array_t<double> Shaped(const pyb::handle& value, const std::vector<pyb::ssize_t>& shape, const std::string& what);

// Every realism parameter by its dotted name (core/realism_fields.h).
pyb::dict RealismDict(const SensorRealism& realism);
// A dict of name -> number, as given.
std::vector<std::pair<std::string, double>> RealismValues(const pyb::object& values);

}  // namespace turf::py
