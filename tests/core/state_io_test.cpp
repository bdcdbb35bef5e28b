// The snapshot format's one field list (core/state_io.h): a struct listed once
// saves and restores bit for bit, and a restore refuses what no save writes.
#include "core/state_io.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace turf {
namespace {

enum class Colour : uint8_t { kRed, kGreen, kCount };

struct Item {
  int32_t id = 0;
  double weight = 0.0;
};

struct Record {
  Colour colour = Colour::kRed;
  bool flag = false;
  double gain = 0.0;
  std::array<double, 3> axis{};
  Item item;
  std::vector<Item> items;
  std::vector<double> joints;
  int64_t count = 0;
};

template <class Io>
void Fields(Io& io, IoRef<Io, Item> i) {
  io(i.id, i.weight);
}

constexpr size_t kMaxItems = 4;
constexpr size_t kJoints = 2;

template <class Io>
void Fields(Io& io, IoRef<Io, Record> r) {
  io(InRange(r.colour, Colour::kCount), r.flag, FiniteValue(r.gain), r.axis, r.item, Sized(r.items, kMaxItems),
     Exactly(r.joints, kJoints), r.count);
  io.Check(r.count >= 0, "negative count");
}

Record Sample() {
  Record r;
  r.colour = Colour::kGreen;
  r.flag = true;
  r.gain = 0.1;
  r.axis = {1.0, -2.5, std::nextafter(3.0, 4.0)};
  r.item = {7, 1.25};
  r.items = {{1, 0.5}, {2, -0.25}};
  r.joints = {0.3, -0.7};
  r.count = 42;
  return r;
}

std::string Save(const Record& r) {
  StateWriter out;
  out(r);
  return out.Take();
}

// "" when the bytes restored whole into *r, else why not.
std::string Restore(const std::string& bytes, Record* r) {
  StateReader in(bytes);
  in(*r);
  if (!in.ok()) return in.error();
  return in.AtEnd() ? "" : "bytes left over";
}

TEST(StateIo, AStructListedOnceRoundTripsBitForBit) {
  const Record a = Sample();
  const std::string bytes = Save(a);
  Record b;
  ASSERT_EQ(Restore(bytes, &b), "");
  EXPECT_EQ(b.colour, a.colour);
  EXPECT_EQ(b.flag, a.flag);
  EXPECT_EQ(b.gain, a.gain);
  EXPECT_EQ(b.axis, a.axis);
  EXPECT_EQ(b.item.id, a.item.id);
  EXPECT_EQ(b.item.weight, a.item.weight);
  ASSERT_EQ(b.items.size(), a.items.size());
  EXPECT_EQ(b.items[1].id, 2);
  EXPECT_EQ(b.items[1].weight, -0.25);
  EXPECT_EQ(b.joints, a.joints);
  EXPECT_EQ(b.count, a.count);
  EXPECT_EQ(Save(b), bytes);
}

// The layout the visitor writes is the one the single Put/Get calls write: fields in order, no padding, lengths as
// 64-bit counts before the vectors.
TEST(StateIo, TheBytesAreTheFieldsInOrderWithoutPadding) {
  const std::string bytes = Save(Sample());
  const size_t expected = 1 + 1 + 8 + 3 * 8 + (4 + 8) + 8 + 2 * (4 + 8) + 8 + 2 * 8 + 8;
  ASSERT_EQ(bytes.size(), expected);
  EXPECT_EQ(bytes[0], 1);  // kGreen
  EXPECT_EQ(bytes[1], 1);  // true
}

TEST(StateIo, ARestoreRefusesWhatNoSaveWrites) {
  const std::string good = Save(Sample());
  Record r;
  std::string bad = good;
  bad[0] = 2;  // Colour::kCount
  EXPECT_EQ(Restore(bad, &r), "enum value out of range");

  Record nan = Sample();
  nan.gain = NAN;
  EXPECT_EQ(Restore(Save(nan), &r), "value not finite");

  Record many = Sample();
  many.items.resize(kMaxItems + 1);
  EXPECT_EQ(Restore(Save(many), &r), "length out of range");

  Record short_joints = Sample();
  short_joints.joints.resize(1);
  EXPECT_EQ(Restore(Save(short_joints), &r), "wrong vector length");

  Record negative = Sample();
  negative.count = -1;
  EXPECT_EQ(Restore(Save(negative), &r), "negative count");

  EXPECT_EQ(Restore(good.substr(0, good.size() - 1), &r), "truncated");
  EXPECT_EQ(Restore(good + "x", &r), "bytes left over");
}

// A failed check keeps the first failure; a check after a truncation does not replace its reason.
TEST(StateIo, TheFirstFailureIsKept) {
  Record bad = Sample();
  bad.count = -1;
  std::string bytes = Save(bad);
  bytes[0] = 9;  // the colour fails first
  Record r;
  EXPECT_EQ(Restore(bytes, &r), "enum value out of range");
}

}  // namespace
}  // namespace turf
