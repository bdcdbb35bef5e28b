// Typed realism changes (loader/realism_change.h) and the parameter table
// against what else names the parameters: the YAML loader's keys, CheckRealism's
// ranges, the IDL's RealismParameter enum and README's table.
#include "loader/realism_change.h"
#include "tests/support/source_files.h"

#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>

#include "core/realism_fields.h"

namespace turf {
namespace {

const char* JitterKindName(double v) {
  static const char* const kNames[] = {"gaussian", "uniform", "exponential"};
  return kNames[static_cast<int>(v)];
}

// Nested YAML flow maps from dotted names ("camera.link.latency: 0.01" ->
// camera: {link: {latency: 0.01}}). A link's burst map is written only when
// its burst.enabled row is 1 (in YAML, a burst map present means enabled).
struct YamlNode {
  std::map<std::string, YamlNode> children;
  std::string value;
  std::string Text() const {
    if (children.empty()) return value;
    std::string out = "{";
    for (const auto& [key, child] : children) out += (out.size() > 1 ? ", " : "") + key + ": " + child.Text();
    return out + "}";
  }
};

std::string YamlOf(const SensorRealism& r, std::optional<RealismField> only = std::nullopt, double only_value = 0) {
  YamlNode root;
  for (const RealismFieldInfo& info : kRealismFields) {
    if (only && info.field != *only) continue;
    const double v = only ? only_value : GetRealismField(r, info.field);
    std::string name = info.name;
    const size_t burst = name.find(".burst.");
    if (name.size() > 8 && name.substr(name.size() - 8) == ".enabled") continue;
    if (!only && burst != std::string::npos) {
      const auto enabled = RealismFieldNamed(name.substr(0, burst) + ".burst.enabled");
      if (!enabled || GetRealismField(r, *enabled) == 0.0) continue;
    }
    YamlNode* node = &root;
    size_t from = 0;
    for (size_t dot = name.find('.'); dot != std::string::npos; from = dot + 1, dot = name.find('.', from))
      node = &node->children[name.substr(from, dot - from)];
    std::string& value = node->children[name.substr(from)].value;
    const std::string unit = info.unit;
    value = unit == "0..2" ? JitterKindName(v) : unit == "0/1" ? (v != 0 ? "true" : "false") : fmt::format("{}", v);
  }
  return root.Text();
}

// The table's names are the YAML keys: every row set to its own value, written
// as YAML by name, reads back the same.
TEST(RealismTable, YamlKeysAreTheTableNames) {
  SensorRealism r;
  for (size_t i = 0; i < kRealismFieldCount; ++i) {
    const RealismFieldInfo& info = kRealismFields[i];
    const std::string unit = info.unit;
    const double v = unit == "0/1"    ? 1.0
                     : unit == "0..2" ? static_cast<double>(i % 3)
                                      : (std::isinf(info.max) ? 1.0 : info.max) * (i + 1) / (kRealismFieldCount + 1);
    ASSERT_EQ(SetRealismField(&r, info.field, v), Error::kOk) << info.name;
  }
  const std::string yaml = YamlOf(r);
  const RealismLoadResult loaded = ParseRealismYaml(yaml);
  ASSERT_TRUE(loaded.realism) << yaml << "\n" << (loaded.errors.empty() ? "" : loaded.errors[0]);
  for (const RealismFieldInfo& info : kRealismFields)
    EXPECT_EQ(GetRealismField(*loaded.realism, info.field), GetRealismField(r, info.field)) << info.name;
}

// The table's ranges are CheckRealism's: each bound passes the loader (which
// checks), a step beyond it fails. Bools and jitter kinds are typed in YAML.
TEST(RealismTable, RangesAreCheckRealisms) {
  for (const RealismFieldInfo& info : kRealismFields) {
    const std::string unit = info.unit;
    if (unit == "0/1" || unit == "0..2") continue;
    for (const double bound : {info.min, info.max}) {
      if (std::isinf(bound)) continue;
      const double step = bound == info.min ? -1e-6 : 1e-6;
      const bool bursty = std::string(info.name).find(".burst.") != std::string::npos;
      // A burst map enables bursts, and an enabled burst needs p_bad_to_good > 0.
      const bool needs_positive = bursty && std::string(info.name).find("p_bad_to_good") != std::string::npos;
      if (!(needs_positive && bound == 0.0)) {
        const std::string at = YamlOf({}, info.field, bound);
        EXPECT_TRUE(ParseRealismYaml(at).realism) << at;
      }
      const std::string beyond = YamlOf({}, info.field, bound + step);
      EXPECT_FALSE(ParseRealismYaml(beyond).realism) << beyond;
    }
  }
}

// idl/SimControl.idl's RealismParameter lists the table's IDL names, in order,
// and nothing else (control_loop.cpp checks each value at compile time).
TEST(RealismTable, IdlEnumIsTheTable) {
  const std::string idl = test::SourceFile("idl/SimControl.idl");
  const size_t begin = idl.find("enum RealismParameter {");
  ASSERT_NE(begin, std::string::npos);
  const size_t end = idl.find("};", begin);
  std::istringstream body(idl.substr(begin, end - begin));
  std::string line;
  std::getline(body, line);
  std::vector<std::string> names;
  while (std::getline(body, line)) {
    const size_t from = line.find_first_not_of(' ');
    if (from == std::string::npos || line.compare(from, 2, "//") == 0) continue;
    names.push_back(line.substr(from, line.find_first_of(", /", from) - from));
  }
  ASSERT_EQ(names.size(), kRealismFieldCount);
  for (size_t i = 0; i < kRealismFieldCount; ++i) EXPECT_EQ(names[i], kRealismFields[i].idl_name) << i;
}

// README.md's realism table is the generated one; to update it, paste the text this test prints.
TEST(RealismTable, ReadmeTableIsTheGeneratedOne) {
  EXPECT_TRUE(
      test::ReadmeSectionIs("<!-- realism-table: generated from core/realism_fields.h by RealismFieldsMarkdown() -->\n",
                            "<!-- /realism-table -->", RealismFieldsMarkdown()));
}

RealismValue Value(RealismField field, double value) { return {static_cast<uint32_t>(field), value}; }

TEST(RealismChange, PresetThenValuesInOrder) {
  SensorRealism current;
  current.camera.robot_vanish = 0.3;  // replaced by the preset
  const RealismChangeResult r = ApplyRealismChange(
      current, {"realistic",
                {Value(RealismField::kCommandLatency, 0.05), Value(RealismField::kCameraLinkJitterKind, 1),
                 Value(RealismField::kCommandLatency, 0.07), Value(RealismField::kCameraBallOcclusion, 0)}});
  ASSERT_TRUE(r.ok()) << r.reason;
  const SensorRealism realistic = *LoadRealism("realistic").realism;
  EXPECT_EQ(r.realism.camera.robot_vanish, realistic.camera.robot_vanish);
  EXPECT_EQ(r.realism.camera.robot_position_stddev, realistic.camera.robot_position_stddev);
  EXPECT_EQ(r.realism.command.latency, 0.07);  // the later value wins
  EXPECT_EQ(r.realism.camera.link.jitter_kind, JitterKind::kUniform);
  EXPECT_FALSE(r.realism.camera.ball_occlusion);
  EXPECT_TRUE(r.realism.command.burst.enabled);  // the preset's, untouched
}

TEST(RealismChange, ValuesAloneChangeOnlyThemselves) {
  SensorRealism current = *LoadRealism("harsh").realism;
  const RealismChangeResult r = ApplyRealismChange(current, {"", {Value(RealismField::kEncoderResolution, 0.01)}});
  ASSERT_TRUE(r.ok()) << r.reason;
  for (const RealismFieldInfo& info : kRealismFields) {
    if (info.field == RealismField::kEncoderResolution) continue;
    EXPECT_EQ(GetRealismField(r.realism, info.field), GetRealismField(current, info.field)) << info.name;
  }
  EXPECT_EQ(r.realism.encoder.resolution, 0.01);
  EXPECT_TRUE(ApplyRealismChange(current, {}).ok());  // nothing to change is fine
}

TEST(RealismChange, RefusalsChangeNothingAndNameTheCulprit) {
  SensorRealism current;
  current.command.latency = 0.02;
  struct Bad {
    RealismChange change;
    Error error;
    const char* named;
  };
  const Bad bad[] = {
      {{"nosuch", {}}, Error::kUnknownPreset, "nosuch"},
      {{"nosuch", {}}, Error::kUnknownPreset, "(presets: harsh, ideal, realistic)"},
      {{"../realism/harsh", {}}, Error::kUnknownPreset, "../realism/harsh"},
      {{"/etc/passwd", {}}, Error::kUnknownPreset, "/etc/passwd"},
      {{"camera: {robot_vanish: 1}", {}}, Error::kUnknownPreset, "camera"},
      {{"harsh.yaml", {}}, Error::kUnknownPreset, "harsh.yaml"},
      {{std::string(1000, 'x'), {}}, Error::kUnknownPreset, "xxx..."},  // quoted, but not at length
      {{"", {Value(RealismField::kCommandLoss, 0.1), Value(RealismField::kCameraLinkLatency, NAN)}},
       Error::kNotFinite,
       "camera.link.latency"},
      {{"", {Value(RealismField::kCommandLoss, 0.1), Value(RealismField::kCameraRobotVanish, 1.5)}},
       Error::kOutOfRange,
       "camera.robot_vanish"},
      {{"", {Value(RealismField::kCameraBallOcclusion, 2)}}, Error::kOutOfRange, "camera.ball_occlusion"},
      {{"harsh", {Value(RealismField::kImuLinkJitterKind, 3)}}, Error::kUnknownEnum, "imu.link.jitter_kind"},
      {{"", {RealismValue{static_cast<uint32_t>(kRealismFieldCount), 0.0}}}, Error::kUnknownEnum, "parameter"},
      {{"", {RealismValue{1000, 0.0}}}, Error::kUnknownEnum, "1000"},
      {{"", {Value(RealismField::kTouchLinkBurstPBadToGood, 0), Value(RealismField::kTouchLinkBurstEnabled, 1)}},
       Error::kInvalidRealism,
       "p_bad_to_good"},
  };
  for (const Bad& b : bad) {
    const RealismChangeResult r = ApplyRealismChange(current, b.change);
    EXPECT_EQ(r.error, b.error) << DescribeRealismChange(b.change) << ": " << r.reason;
    EXPECT_NE(r.reason.find(b.named), std::string::npos) << r.reason;
    EXPECT_LT(r.reason.size(), 200u);
    for (const RealismFieldInfo& info : kRealismFields)
      EXPECT_EQ(GetRealismField(r.realism, info.field), GetRealismField(current, info.field)) << info.name;
  }
}

TEST(RealismChange, ABrokenPresetFileIsInvalidRealism) {
  const std::string dir = ::testing::TempDir() + "/realism_change_test";
  std::filesystem::create_directories(dir);
  std::ofstream(dir + "/broken.yaml") << "camera: {robot_vanish: 7}\n";
  std::ofstream(dir + "/fine.yaml") << "command: {latency: 0.5}\n";
  EXPECT_EQ(ApplyRealismChange({}, {"broken", {}}, dir).error, Error::kInvalidRealism);
  const RealismChangeResult fine = ApplyRealismChange({}, {"fine", {}}, dir);
  ASSERT_TRUE(fine.ok()) << fine.reason;
  EXPECT_EQ(fine.realism.command.latency, 0.5);
  EXPECT_EQ(ApplyRealismChange({}, {"harsh", {}}, dir).error, Error::kUnknownPreset);  // only that directory
}

}  // namespace
}  // namespace turf
