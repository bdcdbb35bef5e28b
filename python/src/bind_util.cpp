#include "python/src/bind_util.h"

#include <fmt/format.h>

#include <limits>

#include "core/realism_fields.h"
#include "python/src/sim_error.h"

namespace turf::py {

namespace {

pyb::array_t<double> ReadOnly(pyb::array_t<double> a) {
  pyb::detail::array_proxy(a.ptr())->flags &= ~pyb::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return a;
}

}  // namespace

pyb::array_t<double> View(const double* data, pyb::ssize_t rows, pyb::ssize_t columns, pyb::handle owner) {
  return ReadOnly(pyb::array_t<double>({rows, columns}, data, owner));
}

pyb::array_t<double> View(const double* data, pyb::ssize_t size, pyb::handle owner) {
  return ReadOnly(pyb::array_t<double>({size}, data, owner));
}

pyb::array_t<double> Copy(const std::vector<double>& values, pyb::ssize_t columns) {
  const auto rows = static_cast<pyb::ssize_t>(values.size()) / columns;
  return pyb::array_t<double>({rows, columns}, values.data());
}

pyb::array_t<double> Copy(const double* data, pyb::ssize_t size) { return pyb::array_t<double>({size}, data); }

int IntOr(const pyb::handle& value, int outside) {
  int overflow = 0;
  const long long v = PyLong_AsLongLongAndOverflow(value.ptr(), &overflow);
  if (overflow != 0 || v < std::numeric_limits<int>::min() || v > std::numeric_limits<int>::max()) {
    PyErr_Clear();
    return outside;
  }
  if (v == -1 && PyErr_Occurred()) {
    PyErr_Clear();
    return outside;
  }
  return static_cast<int>(v);
}

int64_t StepCountOf(const pyb::handle& n) {
  if (!pyb::isinstance<pyb::int_>(n)) Check(Error::kMalformed, "n " + pyb::repr(n).cast<std::string>() + " (an int)");
  return IntOr(n, 0);
}

Team TeamOf(const pyb::object& team) {
  if (pyb::isinstance<pyb::str>(team)) {
    const std::string name = team.cast<std::string>();
    if (name == "blue") return Team::kBlue;
    if (name == "yellow") return Team::kYellow;
  } else if (pyb::isinstance<pyb::int_>(team)) {
    const int value = IntOr(team, -1);
    if (value == 0 || value == 1) return static_cast<Team>(value);
  }
  Check(Error::kUnknownTeam, "team " + pyb::repr(team).cast<std::string>() + " (blue or yellow)");
  return Team::kBlue;
}

std::string ShapeText(const std::vector<pyb::ssize_t>& shape) {
  std::string text;
  for (pyb::ssize_t d : shape) text += (text.empty() ? "" : " x ") + std::to_string(d);
  return text.empty() ? "()" : text;
}

pyb::array_t<double> Shaped(const pyb::handle& value, const std::vector<pyb::ssize_t>& shape, const std::string& what) {
  const std::string expected = what + ": expected shape " + ShapeText(shape);
  using Array = pyb::array_t<double, pyb::array::c_style | pyb::array::forcecast>;
  Array a;
  try {
    a = Array::ensure(value);
  } catch (const pyb::error_already_set&) {
  }
  if (!a) {
    PyErr_Clear();
    Check(Error::kMalformed, expected + ", got " + pyb::repr(pyb::type::of(value)).cast<std::string>());
  }
  const std::vector<pyb::ssize_t> got(a.shape(), a.shape() + a.ndim());
  if (got != shape) Check(Error::kMalformed, expected + ", got " + ShapeText(got));
  return a;
}

pyb::dict RealismDict(const SensorRealism& realism) {
  pyb::dict d;
  for (const RealismFieldInfo& f : kRealismFields) d[f.name] = GetRealismField(realism, f.field);
  return d;
}

std::vector<std::pair<std::string, double>> RealismValues(const pyb::object& values) {
  std::vector<std::pair<std::string, double>> out;
  if (values.is_none()) return out;
  if (!pyb::isinstance<pyb::dict>(values)) Check(Error::kWrongType, "realism values (a dict of name: number)");
  for (const auto& [key, value] : values.cast<pyb::dict>()) {
    if (!pyb::isinstance<pyb::str>(key)) Check(Error::kWrongType, "realism parameter names (strings)");
    double number = 0.0;
    try {
      number = pyb::float_(pyb::reinterpret_borrow<pyb::object>(value)).cast<double>();
    } catch (const pyb::error_already_set&) {
      Check(Error::kWrongType, "realism parameter '" + key.cast<std::string>() + "' (a number)");
    }
    out.emplace_back(key.cast<std::string>(), number);
  }
  return out;
}

}  // namespace turf::py
