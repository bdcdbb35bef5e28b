#include "kernel/simspark/radio.h"

#include <gtest/gtest.h>

#include "tests/support/state_round_trip.h"

namespace turf::simspark {
namespace {

Speaker Left(int unum, double x, double y) { return {"Alpha", Side::kLeft, unum, {x, y, 0.4}}; }
Speaker Right(int unum, double x, double y) { return {"Beta", Side::kRight, unum, {x, y, 0.4}}; }

TEST(Radio, OwnMessageComesBackAsSelf) {
  Radio radio;
  const Speaker me = Left(2, -3, 1);
  radio.Say(me, "hello", 12.34);
  const std::vector<Heard> heard = radio.Deliver(me, 1);
  ASSERT_EQ(heard.size(), 1u);
  EXPECT_TRUE(heard[0].self);
  EXPECT_EQ(heard[0].team, "Alpha");
  EXPECT_EQ(heard[0].message, "hello");
  EXPECT_DOUBLE_EQ(heard[0].game_time, 12.34);
  // An opponent with the same number is someone else.
  const std::vector<Heard> other = radio.Deliver(Right(2, 0, 0), 1);
  ASSERT_EQ(other.size(), 1u);
  EXPECT_FALSE(other[0].self);
}

TEST(Radio, DirectionInTheListenersTeamFrame) {
  Radio radio;
  radio.Say(Left(1, 0, 5), "up", 0);
  const std::vector<Heard> to_left = radio.Deliver(Left(2, 0, 0), 1);
  ASSERT_EQ(to_left.size(), 1u);
  EXPECT_NEAR(to_left[0].direction, 90.0, 1e-9);
  const std::vector<Heard> to_right = radio.Deliver(Right(1, 0, 0), 1);  // right team: x, y negated
  ASSERT_EQ(to_right.size(), 1u);
  EXPECT_NEAR(to_right[0].direction, -90.0, 1e-9);
  EXPECT_EQ(to_right[0].team, "Alpha");
  radio.EndCycle();
  radio.Say(Right(3, -4, 0), "x", 0);
  const std::vector<Heard> behind = radio.Deliver(Right(1, 0, 0), 3);  // speaker at field -x = team frame +x
  ASSERT_EQ(behind.size(), 1u);
  EXPECT_NEAR(behind[0].direction, 0.0, 1e-9);
}

TEST(Radio, HeardWithinFiftyMetres) {
  Radio radio;
  radio.Say(Right(1, 10, 0), "near", 0);
  EXPECT_EQ(radio.Deliver(Left(1, -40, 0), 1).size(), 1u);  // exactly 50 m
  EXPECT_EQ(radio.Deliver(Left(2, -40.1, 0), 1).size(), 0u);
  EXPECT_EQ(radio.Deliver(Left(3, 10, 49.9), 1).size(), 1u);
}

TEST(Radio, OneTeammateAndOneOpponentMessagePerTwoCycles) {
  Radio radio;
  const Speaker listener = Left(1, 0, 0);
  radio.Say(Left(2, 1, 0), "a", 0);
  radio.Say(Left(3, 2, 0), "b", 0);   // second teammate: lost
  radio.Say(Right(4, 3, 0), "c", 0);  // opponent: own capacity
  radio.Say(Right(5, 3, 0), "d", 0);  // lost
  radio.Say(listener, "me", 0);       // self: always
  std::vector<Heard> heard = radio.Deliver(listener, 10);
  ASSERT_EQ(heard.size(), 3u);  // as the reference's HearPerceptor: self, teammate, opponent
  EXPECT_EQ(heard[0].message, "me");
  EXPECT_EQ(heard[1].message, "a");
  EXPECT_EQ(heard[2].message, "c");
  radio.EndCycle();

  radio.Say(Left(2, 1, 0), "e", 0.02);
  radio.Say(listener, "me2", 0.02);
  heard = radio.Deliver(listener, 11);  // one cycle later: teammates still over capacity
  ASSERT_EQ(heard.size(), 1u);
  EXPECT_EQ(heard[0].message, "me2");
  radio.EndCycle();

  radio.Say(Left(3, 1, 0), "f", 0.04);
  heard = radio.Deliver(listener, 12);
  ASSERT_EQ(heard.size(), 1u);
  EXPECT_EQ(heard[0].message, "f");
  // Another listener's capacity is its own.
  EXPECT_EQ(radio.Deliver(Left(4, 0, 0), 12).size(), 1u);
}

// The reference's SayEffector keeps one message per agent and cycle: the last.
TEST(Radio, ASpeakersLastMessageOfTheCycleIsTheOneSaid) {
  Radio radio;
  const Speaker listener = Left(1, 0, 0);
  radio.Say(Right(4, 3, 0), "first", 0);
  radio.Say(listener, "mine1", 0);
  radio.Say(Right(4, 3, 0), "second", 0);
  radio.Say(listener, "mine2", 0);
  const std::vector<Heard> heard = radio.Deliver(listener, 1);
  ASSERT_EQ(heard.size(), 2u);
  EXPECT_EQ(heard[0].message, "mine2");
  EXPECT_TRUE(heard[0].self);
  EXPECT_EQ(heard[1].message, "second");
}

TEST(Radio, CapacityRecoversAfterSilenceAndEndCycleForgetsMessages) {
  Radio radio;
  const Speaker listener = Right(1, 0, 0);
  radio.Say(Right(2, 1, 0), "a", 0);
  ASSERT_EQ(radio.Deliver(listener, 1).size(), 1u);
  radio.EndCycle();
  EXPECT_TRUE(radio.Deliver(listener, 2).empty());
  radio.Say(Right(2, 1, 0), "b", 0);
  radio.Say(Right(3, 1, 0), "c", 0);
  const std::vector<Heard> heard = radio.Deliver(listener, 100);  // long silence: still only one
  ASSERT_EQ(heard.size(), 1u);
  EXPECT_EQ(heard[0].message, "b");
}

}  // namespace
}  // namespace turf::simspark

namespace turf::simspark {
namespace {

TEST(RadioSnapshot, MessagesInFlightAndCapacitiesRoundTrip) {
  Radio radio;
  radio.Say(Left(1, 0, 0), "one", 1.0);
  radio.Deliver(Left(2, 1, 0), 1);  // spends listener 2's teammate budget
  radio.Say(Right(3, 5, 5), "three", 1.0);
  const std::string bytes = test::Saved(radio);
  Radio copy;
  ASSERT_EQ(test::RestoreAll(bytes, &copy), "");
  // Listener 2 spent its budget at cycle 1: hears only the opponent at cycle 2.
  for (Radio* r : {&radio, &copy}) {
    const std::vector<Heard> heard = r->Deliver(Left(2, 1, 0), 2);
    ASSERT_EQ(heard.size(), 1u);
    EXPECT_EQ(heard[0].message, "three");
  }
  // Truncated: refused, the radio unchanged.
  Radio empty;
  EXPECT_NE(test::RestoreAll(bytes.substr(0, bytes.size() - 1), &empty), "");
  EXPECT_TRUE(empty.Deliver(Left(1, 0, 0), 1).empty());
}

}  // namespace
}  // namespace turf::simspark
