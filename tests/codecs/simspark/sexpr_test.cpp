#include "codecs/simspark/sexpr.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>

namespace turf::simspark {
namespace {

TEST(SExpr, ParsesNestedListsAndConcatenatedPredicates) {
  const SExprParse p = ParseSExprs("(GS (t 0.00) (pm PlayOn))(syn)");
  ASSERT_EQ(p.error, SExprError::kOk);
  ASSERT_EQ(p.exprs.size(), 2u);
  const SExpr& gs = p.exprs[0];
  EXPECT_TRUE(gs.is_list);
  ASSERT_EQ(gs.items.size(), 3u);
  EXPECT_EQ(gs.items[0].atom, "GS");
  EXPECT_TRUE(gs.IsCall("GS"));
  EXPECT_FALSE(gs.IsCall("G"));
  ASSERT_NE(gs.Child("pm"), nullptr);
  ASSERT_EQ(gs.Child("pm")->items.size(), 2u);
  EXPECT_EQ(gs.Child("pm")->items[1].atom, "PlayOn");
  EXPECT_EQ(gs.Child("t")->items[1].atom, "0.00");
  EXPECT_EQ(gs.Child("sl"), nullptr);
  EXPECT_EQ(gs.Head(), "GS");
  EXPECT_TRUE(p.exprs[1].IsCall("syn"));
  EXPECT_EQ(p.exprs[1].items.size(), 1u);
}

TEST(SExpr, AnyWhitespaceSeparatesTokens) {
  const SExprParse p = ParseSExprs(" \t(\nbeam\r\n-5.0\v1.5\f0.0 )  ( syn )\n");
  ASSERT_EQ(p.error, SExprError::kOk);
  ASSERT_EQ(p.exprs.size(), 2u);
  ASSERT_EQ(p.exprs[0].items.size(), 4u);
  EXPECT_EQ(p.exprs[0].items[1].atom, "-5.0");
  EXPECT_EQ(p.exprs[0].items[2].atom, "1.5");
  EXPECT_EQ(p.exprs[0].items[3].atom, "0.0");
  EXPECT_TRUE(p.exprs[1].IsCall("syn"));
}

TEST(SExpr, EmptyInputAndEmptyListsAreFine) {
  EXPECT_EQ(ParseSExprs("").error, SExprError::kOk);
  EXPECT_TRUE(ParseSExprs("  \n ").exprs.empty());
  const SExprParse p = ParseSExprs("()(())");
  ASSERT_EQ(p.error, SExprError::kOk);
  ASSERT_EQ(p.exprs.size(), 2u);
  EXPECT_TRUE(p.exprs[0].items.empty());
  EXPECT_EQ(p.exprs[0].Head(), "");
  EXPECT_FALSE(p.exprs[0].IsCall(""));
  EXPECT_EQ(p.exprs[1].Head(), "");  // headed by a list
}

TEST(SExpr, ParenthesesEndAtomsWithoutSpace) {
  const SExprParse p = ParseSExprs("(a(b)c)");
  ASSERT_EQ(p.error, SExprError::kOk);
  ASSERT_EQ(p.exprs[0].items.size(), 3u);
  EXPECT_EQ(p.exprs[0].items[0].atom, "a");
  EXPECT_TRUE(p.exprs[0].items[1].IsCall("b"));
  EXPECT_EQ(p.exprs[0].items[2].atom, "c");
}

// The calls of WalkSExprs written out again: "(", each atom and ")", separated by one space.
class Transcript final : public SExprVisitor {
 public:
  void Open() override { text += "( "; }
  void Atom(std::string_view atom) override { text.append(atom).append(" "); }
  void Close() override { text += ") "; }
  std::string text;
};

void Write(const SExpr& e, std::string* out) {
  if (!e.is_list) {
    out->append(e.atom).append(" ");
    return;
  }
  *out += "( ";
  for (const SExpr& item : e.items) Write(item, out);
  *out += ") ";
}

void ExpectError(std::string_view text, SExprError error, size_t offset, const SExprLimits& limits = {}) {
  const SExprParse p = ParseSExprs(text, limits);
  EXPECT_EQ(p.error, error) << text;
  EXPECT_EQ(p.offset, offset) << text;
  EXPECT_TRUE(p.exprs.empty()) << text;  // all or nothing
  Transcript walk;
  size_t walk_offset = 99;
  EXPECT_EQ(WalkSExprs(text, limits, walk, &walk_offset), error) << text;  // the tree's grammar is the walk's
  EXPECT_EQ(walk_offset, offset) << text;
}

TEST(SExpr, TheWalkVisitsTheTreeInTextOrder) {
  const std::string text = " (GS (t 0.00) (pm PlayOn))(syn)( )((a)(b (c d)))";
  const SExprParse p = ParseSExprs(text);
  ASSERT_EQ(p.error, SExprError::kOk);
  std::string tree;
  for (const SExpr& e : p.exprs) Write(e, &tree);
  Transcript walk;
  size_t offset = 99;
  ASSERT_EQ(WalkSExprs(text, {}, walk, &offset), SExprError::kOk);
  EXPECT_EQ(offset, 0u);
  EXPECT_EQ(walk.text, tree);
  EXPECT_EQ(walk.text, "( GS ( t 0.00 ) ( pm PlayOn ) ) ( syn ) ( ) ( ( a ) ( b ( c d ) ) ) ");
}

// Each refusal names the byte it stopped at: an unclosed list at the end, an extra ')' at itself, a byte outside
// printable ASCII at itself, an atom outside any list at its first byte.
TEST(SExpr, RefusalsReportTheirByte) {
  const struct {
    std::string text;
    SExprError error;
    size_t offset;
  } kCases[] = {
      {"(syn)(he1 1", SExprError::kUnbalancedOpen, 11},
      {"(", SExprError::kUnbalancedOpen, 1},
      {"(syn))", SExprError::kUnbalancedClose, 5},
      {")", SExprError::kUnbalancedClose, 0},
      {std::string("(say a\0b)", 9), SExprError::kBadByte, 6},
      {"(say \x80)", SExprError::kBadByte, 5},
      {"(say \xff)", SExprError::kBadByte, 5},
      {"\x01(syn)", SExprError::kBadByte, 0},
      {"(syn)\x7f", SExprError::kBadByte, 5},
      {"syn", SExprError::kTopLevelAtom, 0},
      {"(syn) x", SExprError::kTopLevelAtom, 6},
  };
  for (const auto& c : kCases) ExpectError(c.text, c.error, c.offset);
}

TEST(SExpr, DepthIsLimited) {
  std::string ok(16, '(');
  ok += std::string(16, ')');
  EXPECT_EQ(ParseSExprs(ok).error, SExprError::kOk);
  std::string deep(17, '(');
  deep += std::string(17, ')');
  ExpectError(deep, SExprError::kTooDeep, 16);
  // No stack overflow however deep: refused at the first byte too many.
  ExpectError(std::string(100000, '('), SExprError::kTooDeep, 16);
  ExpectError("((a))", SExprError::kTooDeep, 1, SExprLimits{1, 4096, 256});
}

TEST(SExpr, NodeCountIsLimited) {
  SExprLimits limits;
  limits.max_nodes = 4;
  EXPECT_EQ(ParseSExprs("(a b c)", limits).error, SExprError::kOk);  // 4 nodes
  ExpectError("(a b c d)", SExprError::kTooManyNodes, 7, limits);
  ExpectError("(a)(b)(c)", SExprError::kTooManyNodes, 6, limits);
  std::string many;
  for (int i = 0; i < 3000; ++i) many += "(x)";
  EXPECT_EQ(ParseSExprs(many).error, SExprError::kTooManyNodes);  // default 4096
}

TEST(SExpr, AtomLengthIsLimited) {
  const std::string at_limit = "(" + std::string(256, 'a') + ")";
  const SExprParse p = ParseSExprs(at_limit);
  ASSERT_EQ(p.error, SExprError::kOk);
  EXPECT_EQ(p.exprs[0].items[0].atom.size(), 256u);
  ExpectError("(say " + std::string(257, 'a') + ")", SExprError::kAtomTooLong, 5);
}

TEST(SExprNumbers, DecimalNumbersParseWhole) {
  struct Case {
    const char* text;
    double value;
  };
  for (const Case& c : {Case{"1.5", 1.5}, Case{"-2", -2.0}, Case{"+3", 3.0}, Case{".5", 0.5}, Case{"1.", 1.0},
                        Case{"1e3", 1000.0}, Case{"-2.5E-1", -0.25}, Case{"0", 0.0}, Case{"1e-400", 0.0}}) {
    double v = -99;
    EXPECT_EQ(ParseDouble(c.text, &v), NumberError::kOk) << c.text;
    EXPECT_DOUBLE_EQ(v, c.value) << c.text;
  }
}

// ParseDouble reads a decimal as strtod does, bit for bit (both round correctly): long mantissas, halfway cases,
// subnormals and underflow to zero included.
TEST(SExprNumbers, ReadsWhatStrtodReads) {
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<int> digit(0, 9), length(1, 30), exponent(-340, 310), shape(0, 3);
  for (int i = 0; i < 20000; ++i) {
    std::string text = shape(rng) == 0 ? "-" : (shape(rng) == 0 ? "+" : "");
    const int n = length(rng);
    for (int k = 0; k < n; ++k) text += static_cast<char>('0' + digit(rng));
    if (shape(rng) != 0) text.insert(text.size() - static_cast<size_t>(digit(rng) % n), ".");
    if (shape(rng) != 0) text += "e" + std::to_string(exponent(rng));
    const double expected = std::strtod(text.c_str(), nullptr);
    double v = -99;
    if (!std::isfinite(expected)) {
      EXPECT_EQ(ParseDouble(text, &v), NumberError::kNotFinite) << text;
      continue;
    }
    ASSERT_EQ(ParseDouble(text, &v), NumberError::kOk) << text;
    EXPECT_EQ(std::memcmp(&v, &expected, sizeof v), 0) << text << " read " << v << ", strtod " << expected;
  }
}

TEST(SExprNumbers, PartialOrOtherNotationsAreBad) {
  for (const char* text : {"", "1.0abc", "abc", "0x10", "1e", "1e+", "--1", "+", ".", "1.2.3", " 1", "1,5", "e5"}) {
    double v = -99;
    EXPECT_EQ(ParseDouble(text, &v), NumberError::kBad) << text;
    EXPECT_EQ(v, -99) << text;  // untouched
  }
}

TEST(SExprNumbers, NonFiniteIsItsOwnError) {
  for (const char* text : {"nan", "NaN", "-nan", "inf", "-INF", "+Infinity", "1e999", "-1e400"}) {
    double v = -99;
    EXPECT_EQ(ParseDouble(text, &v), NumberError::kNotFinite) << text;
  }
}

TEST(SExprNumbers, IntegersAreWholeAndInRange) {
  int v = 0;
  EXPECT_TRUE(ParseInt("7", &v));
  EXPECT_EQ(v, 7);
  EXPECT_TRUE(ParseInt("-3", &v));
  EXPECT_EQ(v, -3);
  EXPECT_TRUE(ParseInt("+12", &v));
  EXPECT_EQ(v, 12);
  EXPECT_TRUE(ParseInt("2147483647", &v));
  EXPECT_EQ(v, 2147483647);
  EXPECT_TRUE(ParseInt("-2147483648", &v));
  EXPECT_EQ(v, -2147483647 - 1);
  for (const char* text : {"2147483648", "-2147483649", "99999999999999999999", "1.0", "1e2", "", "-", "7a", "0x1"})
    EXPECT_FALSE(ParseInt(text, &v)) << text;
}

}  // namespace
}  // namespace turf::simspark
