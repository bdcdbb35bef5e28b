// The snapshot format's one field list (core/state_io.h): a struct listed once
// saves and restores bit for bit, and a restore refuses what no save writes.
#include "core/state_io.h"

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <utility>
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

template <class T>
std::string Save(const T& v) {
  StateWriter out;
  out(v);
  return out.Take();
}

// "" when the bytes restored whole into *v, else why not.
template <class T>
std::string Restore(const std::string& bytes, T* v) {
  StateReader in(bytes);
  in(*v);
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

// An enum without kCount names its count next to it.
enum class Hand { kLeft, kRight };
constexpr Hand EnumCount(Hand) { return static_cast<Hand>(2); }

struct League {
  std::optional<std::string> name;
  std::optional<Hand> kick_off;
  Hand hand = Hand::kLeft;
  int score[2] = {0, 0};
  Eigen::Vector3d ball = Eigen::Vector3d::Zero();
  Eigen::Quaterniond pose = Eigen::Quaterniond::Identity();
  std::map<std::pair<Hand, int>, std::vector<double>> players;
};

template <class Io>
void Fields(Io& io, IoRef<Io, League> l) {
  io(l.name, l.kick_off, l.hand, l.score, l.ball, l.pose, l.players);
}

League SampleLeague() {
  League l;
  l.name = "Alpha";
  l.kick_off = Hand::kRight;
  l.hand = Hand::kRight;
  l.score[1] = 3;
  l.ball = Eigen::Vector3d(1, -2, 0.04);
  l.pose = Eigen::Quaterniond(Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ()));
  l.players[{Hand::kLeft, 1}] = {0.5};
  l.players[{Hand::kRight, 7}] = {};
  return l;
}

TEST(StateIo, OptionalsStringsArraysEigenAndMapsRoundTrip) {
  const League a = SampleLeague();
  League b;
  b.name.reset();
  ASSERT_EQ(Restore(Save(a), &b), "");
  EXPECT_EQ(b.name, a.name);
  EXPECT_EQ(b.kick_off, a.kick_off);
  EXPECT_EQ(b.hand, a.hand);
  EXPECT_EQ(b.score[1], 3);
  EXPECT_EQ(b.ball, a.ball);
  EXPECT_EQ(b.pose.coeffs(), a.pose.coeffs());
  EXPECT_EQ(b.players, a.players);
  EXPECT_EQ(Save(b), Save(a));

  League empty = SampleLeague();
  empty.name.reset();
  empty.kick_off.reset();
  League c = SampleLeague();
  ASSERT_EQ(Restore(Save(empty), &c), "");
  EXPECT_FALSE(c.name.has_value());
  EXPECT_FALSE(c.kick_off.has_value());
}

TEST(StateIo, TheSameValuesRefusedInsideOptionalsKeysAndEigen) {
  League r;
  League bad_enum = SampleLeague();
  bad_enum.kick_off = static_cast<Hand>(2);
  EXPECT_EQ(Restore(Save(bad_enum), &r), "enum value out of range");

  League bad_key = SampleLeague();
  bad_key.players[{static_cast<Hand>(5), 1}] = {};
  EXPECT_EQ(Restore(Save(bad_key), &r), "enum value out of range");

  League nan_ball = SampleLeague();
  nan_ball.ball.y() = NAN;
  EXPECT_EQ(Restore(Save(nan_ball), &r), "value not finite");

  League inf_pose = SampleLeague();
  inf_pose.pose.w() = INFINITY;
  EXPECT_EQ(Restore(Save(inf_pose), &r), "value not finite");

  League long_name = SampleLeague();
  long_name.name = std::string(kMaxSnapshotString + 1, 'x');
  EXPECT_EQ(Restore(Save(long_name), &r), "length out of range");
}

// A map's keys come sorted from a save; the same key twice never does.
TEST(StateIo, AMapRefusesAKeyTwice) {
  std::map<int, int> m = {{1, 10}, {2, 20}};
  std::string bytes = Save(m);
  // Rewrite the second key (after the count and the first pair) to the first's.
  const size_t second_key = sizeof(uint64_t) + 2 * sizeof(int);
  bytes[second_key] = 1;
  std::map<int, int> r;
  EXPECT_EQ(Restore(bytes, &r), "a key twice");
}

// A restore that fails part way leaves a vector no longer than what it read: a length that claims more than the
// bytes hold fails as truncated, without reading on.
TEST(StateIo, AClaimedLengthBeyondTheBytesIsTruncated) {
  StateWriter out;
  out.Put<uint64_t>(kMaxSnapshotItems);  // within the cap, far more than follows
  out.Put(1.0);
  std::vector<double> v;
  EXPECT_EQ(Restore(out.Take(), &v), "truncated");
}

}  // namespace
}  // namespace turf
