// A run-time realism change (OP_SET_REALISM) applied to a SensorRealism: start
// from the current realism, replace it with a preset if one is named, then set
// each typed value in order; the result must pass CheckRealism. All or
// nothing: a refusal leaves the realism as it was. Both turf-sim node kinds
// (SSL and legged) call this one function.
// It lives in the loader, not in core, because presets are files
// (configs/realism/<name>.yaml) and core reads no files; it knows no DDS, so
// it is tested without a network (tests/loader/realism_change_test.cpp).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/errors.h"
#include "core/realism_fields.h"
#include "core/sensor_realism.h"
#include "loader/realism_yaml.h"

namespace turf {

struct RealismValue {
  uint32_t parameter = 0;  // a RealismField, as received (may be one this build does not know)
  double value = 0.0;
};

struct RealismChange {
  std::string preset;  // a preset NAME in the preset directory; empty: none. Never YAML, never a path.
  std::vector<RealismValue> values;
};

struct RealismChangeResult {
  Error error = Error::kOk;  // kUnknownPreset, kInvalidRealism, kUnknownEnum, kNotFinite, kOutOfRange
  std::string reason;        // names the preset or parameter; empty when ok
  SensorRealism realism;     // the new realism when ok, else the current one
  bool ok() const { return error == Error::kOk; }
};

RealismChangeResult ApplyRealismChange(const SensorRealism& current, const RealismChange& change,
                                       const std::string& preset_dir = DefaultRealismDir());

// For logs: "preset harsh, camera.link.latency=0.01, command.loss=0.1".
std::string DescribeRealismChange(const RealismChange& change);

}  // namespace turf
