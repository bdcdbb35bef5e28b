#include "core/realism_fields.h"

#include <fmt/format.h>

namespace turf {

namespace {

double AsNumber(double v) { return v; }
double AsNumber(bool v) { return v ? 1.0 : 0.0; }
double AsNumber(JitterKind v) { return static_cast<double>(v); }

// Range and finiteness are checked before; these check what the type needs.
Error Store(double v, double* to) {
  *to = v;
  return Error::kOk;
}
Error Store(double v, bool* to) {
  if (v != 0.0 && v != 1.0) return Error::kOutOfRange;
  *to = v == 1.0;
  return Error::kOk;
}
Error Store(double v, JitterKind* to) {
  if (v != std::floor(v) || v < 0.0 || v >= static_cast<double>(JitterKind::kCount)) return Error::kUnknownEnum;
  *to = static_cast<JitterKind>(static_cast<int>(v));
  return Error::kOk;
}

std::string Bound(double v) {
  if (std::isinf(v)) return v < 0 ? "-inf" : "inf";
  if (v == M_PI) return "pi";
  return fmt::format("{}", v);
}

}  // namespace

const RealismFieldInfo kRealismFields[kRealismFieldCount] = {
#define TURF_REALISM_FIELD_INFO(e, name, idl, member, unit, min, max, meaning) \
  {RealismField::e, name, #idl, unit, min, max, meaning},
    TURF_REALISM_FIELDS(TURF_REALISM_FIELD_INFO)
#undef TURF_REALISM_FIELD_INFO
};

const RealismFieldInfo& Info(RealismField field) { return kRealismFields[static_cast<size_t>(field)]; }

std::optional<RealismField> RealismFieldNamed(std::string_view name) {
  for (const RealismFieldInfo& info : kRealismFields)
    if (name == info.name) return info.field;
  return std::nullopt;
}

double GetRealismField(const SensorRealism& r, RealismField field) {
  switch (field) {
#define TURF_REALISM_FIELD_GET(e, name, idl, member, unit, min, max, meaning) \
  case RealismField::e:                                                       \
    return AsNumber(r.member);
    TURF_REALISM_FIELDS(TURF_REALISM_FIELD_GET)
#undef TURF_REALISM_FIELD_GET
    case RealismField::kCount:
      break;
  }
  return std::nan("");
}

Error SetRealismField(SensorRealism* r, RealismField field, double value) {
  if (field >= RealismField::kCount) return Error::kUnknownEnum;
  if (!std::isfinite(value)) return Error::kNotFinite;
  switch (field) {
#define TURF_REALISM_FIELD_SET(e, name, idl, member, unit, lo, hi, meaning)      \
  case RealismField::e: {                                                        \
    auto v = r->member;                                                          \
    if (const Error error = Store(value, &v); error != Error::kOk) return error; \
    if (value < (lo) || value > (hi)) return Error::kOutOfRange;                 \
    r->member = v;                                                               \
    return Error::kOk;                                                           \
  }
    TURF_REALISM_FIELDS(TURF_REALISM_FIELD_SET)
#undef TURF_REALISM_FIELD_SET
    case RealismField::kCount:
      break;
  }
  return Error::kUnknownEnum;
}

std::string RealismFieldsMarkdown() {
  std::string out =
      "| parameter | unit | range | meaning |\n"
      "| --- | --- | --- | --- |\n";
  for (const RealismFieldInfo& info : kRealismFields)
    out += fmt::format("| `{}` | {} | [{}, {}] | {} |\n", info.name, info.unit, Bound(info.min), Bound(info.max),
                       info.meaning);
  return out;
}

}  // namespace turf
