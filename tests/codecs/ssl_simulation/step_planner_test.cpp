// StepPlanner: whole physics steps for sync requests of any length, the total
// within half a step of the total asked for, the remainder carried in ns.
#include "codecs/ssl_simulation/step_planner.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <vector>

namespace turf::simproto {
namespace {

constexpr int64_t kStepNs = 2'000'000;  // turf-sim's 2 ms

TEST(StepPlanner, SixtiethOfASecondStaysWithinHalfAStepOfTheTotalAtEveryRequest) {
  const int64_t request_ns = ToNanoseconds(1.0 / 60.0);
  ASSERT_EQ(request_ns, 16'666'667);
  StepPlanner planner;
  int64_t steps = 0;
  std::vector<uint32_t> first;
  for (int k = 1; k <= 600; ++k) {
    SCOPED_TRACE(k);
    const uint32_t n = planner.Plan(request_ns, kStepNs);
    if (first.size() < 6) first.push_back(n);
    EXPECT_TRUE(n == 8u || n == 9u) << n;
    steps += n;
    const int64_t simulated_ns = steps * kStepNs;
    EXPECT_LE(std::abs(k * request_ns - simulated_ns), kStepNs / 2);  // the total asked for, in ns
    // ... and the exact k/60 s, give or take the 1/3 ns per request that ns rounding lost.
    EXPECT_LE(std::abs(static_cast<double>(k) * 1e9 / 60.0 - static_cast<double>(simulated_ns)),
              kStepNs / 2 + k * 0.34);
    EXPECT_EQ(planner.carry_ns(), k * request_ns - simulated_ns);
    if (k == 60) {
      EXPECT_EQ(steps, 500);  // 1.000 s
    }
  }
  EXPECT_EQ(steps, 5000);  // 10.000 s
  EXPECT_EQ(first, (std::vector<uint32_t>{8, 9, 8, 8, 9, 8}));
}

TEST(StepPlanner, TheFloatAClientSendsForASixtiethGivesFiveHundredStepsASecond) {
  const int64_t request_ns = FloatSecondsToNanoseconds(1.0f / 60.0f);
  EXPECT_EQ(request_ns, 16'666'668);  // the float reads 0.016666668
  StepPlanner planner;
  int64_t steps = 0;
  for (int k = 1; k <= 600; ++k) {
    steps += planner.Plan(request_ns, kStepNs);
    EXPECT_LE(std::abs(k * request_ns - steps * kStepNs), kStepNs / 2) << k;
    if (k % 60 == 0) {
      EXPECT_EQ(steps, 500 * (k / 60)) << k;
    }
  }
}

// FloatSecondsToNanoseconds reads a float as the shortest decimal that gives it back. The same, spelled out: the
// fewest %g digits that round-trip. Checked over every float in 10 ns .. 1 s with a stride, and some round numbers.
int64_t ShortestDigitsByPrintf(float seconds) {
  char text[32];
  for (int digits = 1; digits <= 9; ++digits) {
    std::snprintf(text, sizeof(text), "%.*g", digits, static_cast<double>(seconds));
    if (std::strtof(text, nullptr) == seconds) break;
  }
  return ToNanoseconds(std::strtod(text, nullptr));
}

TEST(StepPlanner, FloatSecondsAreReadAsTheirShortestDecimal) {
  uint32_t from, to;
  const float lo = 1e-8f, hi = 1.0f;
  std::memcpy(&from, &lo, sizeof(from));
  std::memcpy(&to, &hi, sizeof(to));
  int checked = 0;
  for (uint32_t bits = from; bits <= to; bits += 997) {
    float f;
    std::memcpy(&f, &bits, sizeof(f));
    ASSERT_EQ(FloatSecondsToNanoseconds(f), ShortestDigitsByPrintf(f)) << f;
    ++checked;
  }
  EXPECT_GT(checked, 100000);
  for (float f : {1.0f / 60.0f, 0.016f, 0.002f, 0.1f, 1.0f, 1e-4f})
    EXPECT_EQ(FloatSecondsToNanoseconds(f), ShortestDigitsByPrintf(f)) << f;
  EXPECT_EQ(FloatSecondsToNanoseconds(1.0f / 60.0f), 16'666'668);  // 0.016666668
}

TEST(StepPlanner, AMultipleOfTheStepGivesExactlyThatManySteps) {
  for (int64_t n : {1, 8, 500}) {
    StepPlanner planner;
    for (int k = 0; k < 1000; ++k) ASSERT_EQ(planner.Plan(n * kStepNs, kStepNs), static_cast<uint32_t>(n)) << n;
    EXPECT_EQ(planner.carry_ns(), 0);
  }
  EXPECT_EQ(FloatSecondsToNanoseconds(0.016f), 16'000'000);  // not 16'000'001, the float's binary value
  EXPECT_EQ(FloatSecondsToNanoseconds(0.002f), 2'000'000);
  EXPECT_EQ(FloatSecondsToNanoseconds(1.0f), 1'000'000'000);
}

TEST(StepPlanner, ShareBelowHalfAStepRunsNoneAndIsCarried) {
  StepPlanner planner;
  // 1 ms at 2 ms: 0.5 steps each; halves round up.
  std::vector<uint32_t> got;
  for (int k = 0; k < 6; ++k) got.push_back(planner.Plan(1'000'000, kStepNs));
  EXPECT_EQ(got, (std::vector<uint32_t>{1, 0, 1, 0, 1, 0}));
  EXPECT_EQ(planner.carry_ns(), 0);

  // 1 ns (1e-9 s) at a time: nothing for a long while, never lost.
  StepPlanner tiny;
  ASSERT_EQ(FloatSecondsToNanoseconds(1e-9f), 1);
  int64_t steps = 0;
  for (int k = 1; k <= 999'999; ++k) steps += tiny.Plan(1, kStepNs);
  EXPECT_EQ(steps, 0);
  EXPECT_EQ(tiny.carry_ns(), 999'999);
  EXPECT_EQ(tiny.Plan(1, kStepNs), 1u);  // 1'000'000 ns owed: half a step rounds up
  EXPECT_EQ(tiny.carry_ns(), -1'000'000);
}

TEST(StepPlanner, ZeroNegativeAndOversizedRunNothingAndKeepTheCarry) {
  StepPlanner planner;
  ASSERT_EQ(planner.Plan(16'666'667, kStepNs), 8u);
  const int64_t carry = planner.carry_ns();
  for (int64_t bad : {int64_t{0}, int64_t{-1}, int64_t{-16'666'667}, std::numeric_limits<int64_t>::max(),
                      std::numeric_limits<int64_t>::min()}) {
    EXPECT_EQ(planner.Plan(bad, kStepNs), 0u) << bad;
    EXPECT_EQ(planner.carry_ns(), carry) << bad;
  }
  for (int64_t bad_step : {int64_t{0}, int64_t{-2'000'000}, std::numeric_limits<int64_t>::max()}) {
    EXPECT_EQ(planner.Plan(16'666'667, bad_step), 0u) << bad_step;
    EXPECT_EQ(planner.carry_ns(), carry) << bad_step;
  }
  // Non-finite seconds never become a huge count.
  EXPECT_EQ(FloatSecondsToNanoseconds(std::numeric_limits<float>::quiet_NaN()), 0);
  EXPECT_EQ(FloatSecondsToNanoseconds(std::numeric_limits<float>::infinity()), 0);
}

TEST(StepPlanner, ANewPhysicsStepStartsOver) {
  StepPlanner planner;
  ASSERT_EQ(planner.Plan(16'666'667, kStepNs), 8u);
  ASSERT_NE(planner.carry_ns(), 0);
  EXPECT_EQ(planner.Plan(16'666'667, 1'000'000), 17u);  // 16.67 steps of 1 ms, no 2 ms carry
  EXPECT_EQ(planner.step_ns(), 1'000'000);
  EXPECT_EQ(planner.carry_ns(), -333'333);
}

TEST(StepPlanner, ResetAndRebaseForgetTheCarry) {
  StepPlanner planner;
  ASSERT_EQ(planner.Plan(16'666'667, kStepNs), 8u);
  ASSERT_EQ(planner.Plan(16'666'667, kStepNs), 9u);
  planner.Reset();
  EXPECT_EQ(planner.carry_ns(), 0);
  EXPECT_EQ(planner.step_ns(), 0);
  EXPECT_EQ(planner.Plan(16'666'667, kStepNs), 8u);  // as the first request

  // A request planned with a stale carry ran 9 steps; as the first of a new
  // session it should have run 8: the carry is what the first would leave.
  planner.Rebase(16'666'667, 9);
  EXPECT_EQ(planner.carry_ns(), 16'666'667 - 18'000'000);
  int64_t steps = 9;
  for (int k = 2; k <= 60; ++k) {
    steps += planner.Plan(16'666'667, kStepNs);
    EXPECT_LE(std::abs(k * 16'666'667 - steps * kStepNs), kStepNs / 2) << k;
  }
  EXPECT_EQ(steps, 500);
}

}  // namespace
}  // namespace turf::simproto
