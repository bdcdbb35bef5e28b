#include "loader/realism_change.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <filesystem>

#include "loader/realism_yaml.h"

namespace turf {

namespace {

bool PlainName(const std::string& s) {
  return !s.empty() && s.size() <= 64 &&
         s.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789_-") == std::string::npos;
}

}  // namespace

RealismChangeResult ApplyRealismChange(const SensorRealism& current, const RealismChange& change,
                                       const std::string& preset_dir) {
  RealismChangeResult result;
  result.realism = current;
  auto refuse = [&](Error error, std::string reason) {
    result.error = error;
    result.reason = std::move(reason);
    result.realism = current;
    return result;
  };
  SensorRealism realism = current;
  if (!change.preset.empty()) {
    std::error_code ec;
    if (!PlainName(change.preset) || !std::filesystem::is_regular_file(preset_dir + "/" + change.preset + ".yaml", ec))
      return refuse(Error::kUnknownPreset,
                    fmt::format("no realism preset \"{}\" (presets: {})",
                                change.preset.size() <= 64 ? change.preset : change.preset.substr(0, 64) + "...",
                                fmt::join(RealismPresets(preset_dir), ", ")));
    const RealismLoadResult loaded = LoadRealism(change.preset, preset_dir, /*allow_paths=*/false);
    if (!loaded.realism)
      return refuse(Error::kInvalidRealism, fmt::format("realism preset \"{}\": {}", change.preset,
                                                        loaded.errors.empty() ? "unusable" : loaded.errors.front()));
    realism = *loaded.realism;
  }
  for (size_t i = 0; i < change.values.size(); ++i) {
    const RealismValue& v = change.values[i];
    if (v.parameter >= kRealismFieldCount)
      return refuse(Error::kUnknownEnum, fmt::format("realism value {}: unknown parameter {}", i, v.parameter));
    const RealismField field = static_cast<RealismField>(v.parameter);
    const RealismFieldInfo& info = Info(field);
    const Error e = SetRealismField(&realism, field, v.value);
    if (e == Error::kNotFinite) return refuse(e, fmt::format("{}: not a finite number", info.name));
    if (e == Error::kUnknownEnum)
      return refuse(e,
                    fmt::format("{}: {} is no jitter kind (0 gaussian, 1 uniform, 2 exponential)", info.name, v.value));
    if (e != Error::kOk) {
      const bool flag = std::string(info.unit) == "0/1";
      return refuse(e, flag ? fmt::format("{}: {} is neither 0 nor 1", info.name, v.value)
                            : fmt::format("{}: {} is outside [{}, {}]", info.name, v.value, info.min, info.max));
    }
  }
  if (const char* e = CheckRealism(realism); *e != '\0')
    return refuse(Error::kInvalidRealism, fmt::format("the resulting realism is invalid: {}", e));
  result.realism = realism;
  return result;
}

std::string DescribeRealismChange(const RealismChange& change) {
  std::string out = change.preset.empty() ? "" : "preset " + change.preset;
  for (const RealismValue& v : change.values) {
    if (!out.empty()) out += ", ";
    out += v.parameter < kRealismFieldCount
               ? fmt::format("{}={}", Info(static_cast<RealismField>(v.parameter)).name, v.value)
               : fmt::format("#{}={}", v.parameter, v.value);
  }
  return out.empty() ? "no change" : out;
}

}  // namespace turf
