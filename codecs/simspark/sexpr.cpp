#include "codecs/simspark/sexpr.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>

namespace turf::simspark {

namespace {

bool IsSpace(unsigned char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f'; }
bool IsPrintable(unsigned char c) { return c >= 0x21 && c <= 0x7E; }
bool IsDigit(char c) { return c >= '0' && c <= '9'; }

bool EqualsNoCase(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(a[i])) != b[i]) return false;
  return true;
}

// Length of the decimal number at the start of `s` ([+-]? mantissa exponent?), 0 if none.
size_t DecimalLength(std::string_view s) {
  size_t i = 0;
  if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
  size_t digits = 0;
  while (i < s.size() && IsDigit(s[i])) ++i, ++digits;
  if (i < s.size() && s[i] == '.') {
    ++i;
    while (i < s.size() && IsDigit(s[i])) ++i, ++digits;
  }
  if (digits == 0) return 0;
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    size_t j = i + 1;
    if (j < s.size() && (s[j] == '+' || s[j] == '-')) ++j;
    size_t exp_digits = 0;
    while (j < s.size() && IsDigit(s[j])) ++j, ++exp_digits;
    if (exp_digits == 0) return 0;
    i = j;
  }
  return i;
}

// How many items each list holds, the top level first and then the lists in the order they open: what the parse
// reserves, so that no list's items move while it grows. A hint only (the parse checks everything), bounded by the
// limits: it stops at a list too deep or too many.
std::vector<uint32_t> ItemCounts(std::string_view text, const SExprLimits& limits) {
  std::vector<uint32_t> counts{0};
  std::vector<size_t> open{0};  // indices into counts
  size_t i = 0;
  while (i < text.size()) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c == '(') {
      if (open.size() > limits.max_depth || counts.size() > limits.max_nodes) break;
      ++counts[open.back()];
      open.push_back(counts.size());
      counts.push_back(0);
      ++i;
    } else if (c == ')') {
      if (open.size() == 1) break;
      open.pop_back();
      ++i;
    } else if (IsPrintable(c)) {
      ++counts[open.back()];
      while (i < text.size() && IsPrintable(static_cast<unsigned char>(text[i])) && text[i] != '(' && text[i] != ')')
        ++i;
    } else {
      ++i;
    }
  }
  return counts;
}

// A decimal number from_chars cannot represent: an overflow is not finite; an underflow reads as strtod reads it
// (zero or the nearest subnormal).
NumberError OutOfRange(std::string_view atom, double* out) {
  char buffer[401];
  std::memcpy(buffer, atom.data(), atom.size());
  buffer[atom.size()] = '\0';
  const double value = std::strtod(buffer, nullptr);
  if (!std::isfinite(value)) return NumberError::kNotFinite;  // overflow gives HUGE_VAL
  *out = value;
  return NumberError::kOk;
}

}  // namespace

bool SExpr::IsCall(std::string_view name) const {
  return is_list && !items.empty() && !items[0].is_list && items[0].atom == name;
}

const SExpr* SExpr::Child(std::string_view name) const {
  for (const SExpr& item : items)
    if (item.IsCall(name)) return &item;
  return nullptr;
}

std::string_view SExpr::Head() const {
  if (!is_list || items.empty() || items[0].is_list) return {};
  return items[0].atom;
}

namespace {

// The tree of ParseSExprs. open_[i] is the list at depth i+1. Only the innermost list grows (within the room
// reserved for it, from ItemCounts), so the pointers to its ancestors stay valid until they are closed themselves.
class TreeBuilder final : public SExprVisitor {
 public:
  TreeBuilder(std::vector<SExpr>* top, std::vector<uint32_t> counts) : top_(top), counts_(std::move(counts)) {
    top_->reserve(counts_[0]);
  }
  void Open() override {
    std::vector<SExpr>& siblings = open_.empty() ? *top_ : open_.back()->items;
    SExpr& list = siblings.emplace_back();
    list.is_list = true;
    if (++lists_ < counts_.size()) list.items.reserve(counts_[lists_]);
    open_.push_back(&list);
  }
  void Atom(std::string_view atom) override { open_.back()->items.emplace_back().atom.assign(atom); }
  void Close() override { open_.pop_back(); }

 private:
  std::vector<SExpr>* top_;
  std::vector<uint32_t> counts_;
  size_t lists_ = 0;  // lists opened so far
  std::vector<SExpr*> open_;
};

}  // namespace

SExprError WalkSExprs(std::string_view text, const SExprLimits& limits, SExprVisitor& visitor, size_t* offset) {
  size_t depth = 0;
  size_t nodes = 0;
  auto fail = [offset](SExprError error, size_t at) {
    *offset = at;
    return error;
  };
  size_t i = 0;
  while (i < text.size()) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (IsSpace(c)) {
      ++i;
    } else if (c == '(') {
      if (depth >= limits.max_depth) return fail(SExprError::kTooDeep, i);
      if (++nodes > limits.max_nodes) return fail(SExprError::kTooManyNodes, i);
      ++depth;
      visitor.Open();
      ++i;
    } else if (c == ')') {
      if (depth == 0) return fail(SExprError::kUnbalancedClose, i);
      --depth;
      visitor.Close();
      ++i;
    } else if (IsPrintable(c)) {
      if (depth == 0) return fail(SExprError::kTopLevelAtom, i);
      size_t end = i;
      while (end < text.size() && IsPrintable(static_cast<unsigned char>(text[end])) && text[end] != '(' &&
             text[end] != ')') {
        if (end - i >= limits.max_atom) return fail(SExprError::kAtomTooLong, i);
        ++end;
      }
      if (++nodes > limits.max_nodes) return fail(SExprError::kTooManyNodes, i);
      visitor.Atom(text.substr(i, end - i));
      i = end;
    } else {
      return fail(SExprError::kBadByte, i);
    }
  }
  if (depth != 0) return fail(SExprError::kUnbalancedOpen, text.size());
  return fail(SExprError::kOk, 0);
}

SExprParse ParseSExprs(std::string_view text, const SExprLimits& limits) {
  SExprParse result;
  TreeBuilder builder(&result.exprs, ItemCounts(text, limits));
  result.error = WalkSExprs(text, limits, builder, &result.offset);
  if (result.error != SExprError::kOk) result.exprs.clear();
  return result;
}

NumberError ParseDouble(std::string_view atom, double* out) {
  std::string_view word = atom;
  if (!word.empty() && (word[0] == '+' || word[0] == '-')) word.remove_prefix(1);
  if (EqualsNoCase(word, "nan") || EqualsNoCase(word, "inf") || EqualsNoCase(word, "infinity"))
    return NumberError::kNotFinite;
  if (atom.empty() || atom.size() > 400 || DecimalLength(atom) != atom.size()) return NumberError::kBad;
  // from_chars reads the same correctly rounded value as strtod, several times faster, but takes no '+'.
  const char* begin = atom.data() + (atom[0] == '+' ? 1 : 0);
  const char* end = atom.data() + atom.size();
  double value = 0;
  const std::from_chars_result read = std::from_chars(begin, end, value);
  if (read.ec == std::errc::result_out_of_range) return OutOfRange(atom, out);
  if (read.ec != std::errc() || read.ptr != end) return NumberError::kBad;
  *out = value;
  return NumberError::kOk;
}

bool ParseInt(std::string_view atom, int* out) {
  size_t i = 0;
  bool negative = false;
  if (i < atom.size() && (atom[i] == '+' || atom[i] == '-')) negative = atom[i++] == '-';
  if (i == atom.size()) return false;
  long long value = 0;
  for (; i < atom.size(); ++i) {
    if (!IsDigit(atom[i])) return false;
    value = value * 10 + (atom[i] - '0');
    if (value > 2147483648LL) return false;
  }
  if (negative) value = -value;
  if (value > 2147483647LL || value < -2147483648LL) return false;
  *out = static_cast<int>(value);
  return true;
}

}  // namespace turf::simspark
