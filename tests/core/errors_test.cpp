// turf's one error taxonomy (core/errors.h): every name is unique snake_case,
// round-trips through ErrorFromName, and the names users see in counters,
// logs and wire codes are pinned here.
#include "core/errors.h"

#include <gtest/gtest.h>

#include <set>
#include <string>

namespace turf {
namespace {

bool IsSnakeCase(const std::string& s) {
  if (s.empty() || s.front() == '_' || s.back() == '_') return false;
  for (size_t i = 0; i < s.size(); ++i) {
    const char c = s[i];
    if (c == '_') {
      if (s[i - 1] == '_') return false;
    } else if (!((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9'))) {
      return false;
    }
  }
  return !(s.front() >= '0' && s.front() <= '9');
}

TEST(Errors, EveryNameIsUniqueSnakeCaseAndRoundTrips) {
  std::set<std::string> seen;
  for (int i = 0; i < static_cast<int>(Error::kCount); ++i) {
    const Error e = static_cast<Error>(i);
    const std::string name = ErrorName(e);
    EXPECT_TRUE(IsSnakeCase(name)) << i << ": '" << name << "'";
    EXPECT_TRUE(seen.insert(name).second) << "duplicate name '" << name << "'";
    EXPECT_EQ(ErrorFromName(name), e) << name;
    EXPECT_STRNE(ErrorMeaning(e), "?") << name;
    EXPECT_STRNE(ErrorMeaning(e), "") << name;
  }
  EXPECT_EQ(seen.size(), static_cast<size_t>(Error::kCount));
}

TEST(Errors, SnakeCaseCheckRefusesOtherSpellings) {
  EXPECT_TRUE(IsSnakeCase("not_finite"));
  for (const char* bad : {"NotFinite", "not__finite", "_ok", "ok_", "", "too-large", "2d"})
    EXPECT_FALSE(IsSnakeCase(bad)) << "'" << bad << "'";
}

TEST(Errors, PastTheTableHasNoName) {
  EXPECT_STREQ(ErrorName(Error::kCount), "?");
  EXPECT_STREQ(ErrorMeaning(Error::kCount), "?");
  EXPECT_FALSE(ErrorFromName("?").has_value());
  EXPECT_FALSE(ErrorFromName("").has_value());
  EXPECT_FALSE(ErrorFromName("unknown").has_value());
  EXPECT_FALSE(ErrorFromName("Not_Finite").has_value());
}

// Counter names ("command.not_finite", "grsim.malformed", "page.not_json"),
// refusal logs and the simulation protocol's TURF_* codes are built from these.
TEST(Errors, NamesUsersSeeArePinned) {
  const struct {
    Error error;
    const char* name;
  } kPinned[] = {
      {Error::kOk, "ok"},
      {Error::kNotFinite, "not_finite"},
      {Error::kOutOfRange, "out_of_range"},
      {Error::kNoBall, "no_ball"},
      {Error::kEmpty, "empty"},
      {Error::kOversized, "oversized"},
      {Error::kTooLarge, "too_large"},
      {Error::kMalformed, "malformed"},
      {Error::kMissingRequired, "missing_required"},
      {Error::kDuplicateRobot, "duplicate_robot"},
      {Error::kNonPositiveSize, "non_positive_size"},
      {Error::kNoEpoch, "no_epoch"},
      // SimSpark agents' refusals (codecs/simspark: framing, S-expressions, effectors).
      {Error::kParse, "parse"},
      {Error::kUnknownEffector, "unknown_effector"},
      {Error::kBadArguments, "bad_arguments"},
      {Error::kBadSay, "bad_say"},
      {Error::kBadRobotType, "bad_robot_type"},
      {Error::kUnbalancedOpen, "unbalanced_open"},
      {Error::kUnbalancedClose, "unbalanced_close"},
      {Error::kTooDeep, "too_deep"},
      {Error::kTooManyNodes, "too_many_nodes"},
      {Error::kAtomTooLong, "atom_too_long"},
      {Error::kBadByte, "bad_byte"},
      {Error::kTopLevelAtom, "top_level_atom"},
      {Error::kNotJson, "not_json"},
      {Error::kUnknownMode, "unknown_mode"},
      {Error::kDuplicate, "duplicate"},
  };
  for (const auto& p : kPinned) EXPECT_STREQ(ErrorName(p.error), p.name);
}

// The IDL's ControlError follows this order; new kinds are appended, so the
// first ones keep their values on the wire.
TEST(Errors, FirstValuesKeepTheirNumbers) {
  EXPECT_EQ(static_cast<int>(Error::kOk), 0);
  EXPECT_EQ(static_cast<int>(Error::kNotFinite), 1);
  EXPECT_EQ(static_cast<int>(Error::kNoBall), 12);
  EXPECT_EQ(static_cast<int>(Error::kEmpty), 13);
}

}  // namespace
}  // namespace turf
