// The realism parameter table (core/realism_fields.h): one row per field of a
// SensorRealism, no field twice, and typed setting with its refusals.
#include "core/realism_fields.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <set>
#include <string>

#include "core/state_fields.h"

namespace turf {
namespace {

// A value for row i inside the row's range, different from `avoid`.
double ValidValue(const RealismFieldInfo& info, size_t i, double avoid) {
  const std::string unit = info.unit;
  if (unit == "0/1") return avoid == 0.0 ? 1.0 : 0.0;
  if (unit == "0..2") return avoid == 1.0 ? 2.0 : 1.0;
  const double hi = std::isinf(info.max) ? 1.0 : info.max;
  const double v = hi * (0.25 + 0.5 * static_cast<double>(i) / kRealismFieldCount);
  return v == avoid ? v / 2 : v;
}

std::string Snapshot(const SensorRealism& r) {
  StateWriter out;
  out(r);
  return out.Take();
}

TEST(RealismFields, RowsAreInOrderAndNamedOnce) {
  std::set<std::string> names, idl_names;
  for (size_t i = 0; i < kRealismFieldCount; ++i) {
    const RealismFieldInfo& info = kRealismFields[i];
    EXPECT_EQ(static_cast<size_t>(info.field), i) << info.name;
    EXPECT_TRUE(names.insert(info.name).second) << info.name;
    EXPECT_TRUE(idl_names.insert(info.idl_name).second) << info.idl_name;
    std::string idl = "REALISM_";  // REALISM_ + the name, upper case, '_' for '.'
    for (const char c : std::string(info.name)) idl += c == '.' ? '_' : static_cast<char>(std::toupper(c));
    EXPECT_EQ(info.idl_name, idl);
    EXPECT_EQ(RealismFieldNamed(info.name), info.field);
    EXPECT_LE(info.min, info.max) << info.name;
  }
  EXPECT_EQ(RealismFieldNamed("camera.bogus"), std::nullopt);
}

// Every field of a SensorRealism (as its snapshot writes them) is some row:
// two realisms whose memory starts as all 0x00 and all 0x01 bytes (valid for
// doubles, bools and the one-byte jitter kind alike) are equal once every row
// is set to the same value; a field without a row would keep its pattern.
TEST(RealismFields, EveryFieldHasARow) {
  SensorRealism a, b;
  std::memset(static_cast<void*>(&a), 0x00, sizeof a);
  std::memset(static_cast<void*>(&b), 0x01, sizeof b);
  ASSERT_NE(Snapshot(a), Snapshot(b));
  for (size_t i = 0; i < kRealismFieldCount; ++i) {
    const RealismFieldInfo& info = kRealismFields[i];
    const double v = ValidValue(info, i, -1.0);
    ASSERT_EQ(SetRealismField(&a, info.field, v), Error::kOk) << info.name << " = " << v;
    ASSERT_EQ(SetRealismField(&b, info.field, v), Error::kOk) << info.name << " = " << v;
  }
  EXPECT_EQ(Snapshot(a), Snapshot(b)) << "a SensorRealism field has no row in TURF_REALISM_FIELDS";
}

// No field has two rows: setting one row changes that row only.
TEST(RealismFields, EachRowIsItsOwnField) {
  const SensorRealism base;
  for (size_t i = 0; i < kRealismFieldCount; ++i) {
    const RealismFieldInfo& info = kRealismFields[i];
    SensorRealism r = base;
    const double v = ValidValue(info, i, GetRealismField(base, info.field));
    ASSERT_EQ(SetRealismField(&r, info.field, v), Error::kOk) << info.name;
    EXPECT_EQ(GetRealismField(r, info.field), v) << info.name;
    EXPECT_NE(Snapshot(r), Snapshot(base)) << info.name;
    for (const RealismFieldInfo& other : kRealismFields) {
      if (other.field == info.field) continue;
      EXPECT_EQ(GetRealismField(r, other.field), GetRealismField(base, other.field))
          << "setting " << info.name << " changed " << other.name;
    }
  }
}

TEST(RealismFields, SettingRefusesAndChangesNothing) {
  const SensorRealism base;
  struct Bad {
    RealismField field;
    double value;
    Error error;
  };
  for (const Bad& bad : {Bad{RealismField::kCameraRobotVanish, NAN, Error::kNotFinite},
                         Bad{RealismField::kImuGyroBias, INFINITY, Error::kNotFinite},
                         Bad{RealismField::kCameraRobotVanish, 1.5, Error::kOutOfRange},
                         Bad{RealismField::kCommandLatency, -0.001, Error::kOutOfRange},
                         Bad{RealismField::kCameraBallOcclusion, 0.5, Error::kOutOfRange},
                         Bad{RealismField::kCameraLinkJitterKind, 3, Error::kUnknownEnum},
                         Bad{RealismField::kCameraLinkJitterKind, 0.5, Error::kUnknownEnum},
                         Bad{RealismField::kCount, 0, Error::kUnknownEnum}}) {
    SensorRealism r = base;
    EXPECT_EQ(SetRealismField(&r, bad.field, bad.value), bad.error) << bad.value;
    EXPECT_EQ(Snapshot(r), Snapshot(base));
  }
  SensorRealism r;
  EXPECT_EQ(SetRealismField(&r, RealismField::kTouchLinkJitterKind, 2), Error::kOk);
  EXPECT_EQ(r.touch.link.jitter_kind, JitterKind::kExponential);
  EXPECT_EQ(SetRealismField(&r, RealismField::kCommandBurstEnabled, 1), Error::kOk);
  EXPECT_TRUE(r.command.burst.enabled);
  EXPECT_EQ(SetRealismField(&r, RealismField::kImuAccelBias, -3.5), Error::kOk);
  EXPECT_EQ(r.imu.accel_bias, -3.5);
}

TEST(RealismFields, MarkdownHasOneRowPerParameter) {
  const std::string md = RealismFieldsMarkdown();
  EXPECT_EQ(static_cast<size_t>(std::count(md.begin(), md.end(), '\n')), kRealismFieldCount + 2);
  EXPECT_NE(md.find("| `camera.link.latency` | s | [0, 10] | fixed delay of each camera's frames to the network |\n"),
            std::string::npos)
      << md;
  for (const RealismFieldInfo& info : kRealismFields)
    EXPECT_EQ(std::string(info.meaning).find('|'), std::string::npos) << "a '|' would split " << info.name;
}

}  // namespace
}  // namespace turf
