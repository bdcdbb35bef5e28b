#include "codecs/simspark/sexpr.h"

#include <cctype>
#include <cmath>
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

SExprParse ParseSExprs(std::string_view text, const SExprLimits& limits) {
  SExprParse result;
  // open[i] is the list at depth i+1. Only the innermost list grows, so the
  // pointers to its ancestors stay valid until they are closed themselves.
  std::vector<SExpr*> open;
  size_t nodes = 0;
  auto fail = [&](SExprError error, size_t offset) {
    open.clear();
    result.exprs.clear();
    result.error = error;
    result.offset = offset;
    return std::move(result);
  };
  size_t i = 0;
  while (i < text.size()) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (IsSpace(c)) {
      ++i;
    } else if (c == '(') {
      if (open.size() >= limits.max_depth) return fail(SExprError::kTooDeep, i);
      if (++nodes > limits.max_nodes) return fail(SExprError::kTooManyNodes, i);
      std::vector<SExpr>& siblings = open.empty() ? result.exprs : open.back()->items;
      siblings.emplace_back();
      siblings.back().is_list = true;
      open.push_back(&siblings.back());
      ++i;
    } else if (c == ')') {
      if (open.empty()) return fail(SExprError::kUnbalancedClose, i);
      open.pop_back();
      ++i;
    } else if (IsPrintable(c)) {
      if (open.empty()) return fail(SExprError::kTopLevelAtom, i);
      size_t end = i;
      while (end < text.size() && IsPrintable(static_cast<unsigned char>(text[end])) && text[end] != '(' &&
             text[end] != ')') {
        if (end - i >= limits.max_atom) return fail(SExprError::kAtomTooLong, i);
        ++end;
      }
      if (++nodes > limits.max_nodes) return fail(SExprError::kTooManyNodes, i);
      SExpr atom;
      atom.atom.assign(text.substr(i, end - i));
      open.back()->items.push_back(std::move(atom));
      i = end;
    } else {
      return fail(SExprError::kBadByte, i);
    }
  }
  if (!open.empty()) return fail(SExprError::kUnbalancedOpen, text.size());
  return result;
}

NumberError ParseDouble(std::string_view atom, double* out) {
  std::string_view word = atom;
  if (!word.empty() && (word[0] == '+' || word[0] == '-')) word.remove_prefix(1);
  if (EqualsNoCase(word, "nan") || EqualsNoCase(word, "inf") || EqualsNoCase(word, "infinity"))
    return NumberError::kNotFinite;
  if (atom.empty() || atom.size() > 400 || DecimalLength(atom) != atom.size()) return NumberError::kBad;
  char buffer[401];
  std::memcpy(buffer, atom.data(), atom.size());
  buffer[atom.size()] = '\0';
  char* end = nullptr;
  const double value = std::strtod(buffer, &end);
  if (end != buffer + atom.size()) return NumberError::kBad;
  if (!std::isfinite(value)) return NumberError::kNotFinite;  // overflow gives HUGE_VAL
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
