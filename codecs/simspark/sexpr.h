// S-expressions as SimSpark writes and reads them (shared/protocols/simspark.md):
// lists in parentheses and atoms separated by any whitespace, several top-level
// lists simply concatenated, no quoting. The parser is iterative and bounded
// (depth, node count, atom length), so untrusted input costs at most
// O(size) time and O(max_nodes) memory.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/errors.h"

namespace turf::simspark {

struct SExpr {
  bool is_list = false;
  std::string atom;          // when !is_list
  std::vector<SExpr> items;  // when is_list

  // A list whose first item is the atom `name`, e.g. `(beam 1 2 3)` IsCall("beam").
  bool IsCall(std::string_view name) const;
  // The first item that IsCall(name), or nullptr.
  const SExpr* Child(std::string_view name) const;
  // The head atom of a list, "" for an atom, an empty list or a list headed by a list.
  std::string_view Head() const;
};

// turf's one taxonomy (core/errors.h). The parser answers kUnbalancedOpen,
// kUnbalancedClose, kTooDeep, kTooManyNodes, kAtomTooLong, kBadByte (neither
// printable ASCII nor white space, e.g. NUL) and kTopLevelAtom.
using SExprError = turf::Error;
inline const char* SExprErrorName(SExprError error) { return turf::ErrorName(error); }

struct SExprLimits {
  size_t max_depth = 16;  // `(a)` has depth 1
  size_t max_nodes = 4096;
  size_t max_atom = 256;
};

// All or nothing: on an error `exprs` is empty and `offset` is the byte offset of
// the offending byte (for kUnbalancedOpen: the end of the text).
struct SExprParse {
  std::vector<SExpr> exprs;
  SExprError error = SExprError::kOk;
  size_t offset = 0;
};

SExprParse ParseSExprs(std::string_view text, const SExprLimits& limits = {});

// The grammar itself, for a decoder that needs no tree (ParseSExprs is one of its visitors): Open(), Atom() and
// Close() are called in the order of the text, with ParseSExprs' checks and limits. On an error the calls made so
// far are to be discarded, as the parse is all or nothing: WalkSExprs answers the error and sets `offset` to its
// byte (to 0 when there is none).
class SExprVisitor {
 public:
  virtual void Open() = 0;
  virtual void Atom(std::string_view atom) = 0;
  virtual void Close() = 0;

 protected:
  ~SExprVisitor() = default;
};
SExprError WalkSExprs(std::string_view text, const SExprLimits& limits, SExprVisitor& visitor, size_t* offset);

// The detail of a decoder's issue kParse: "<the parser's error> at byte <offset>".
inline std::string SExprErrorAt(SExprError error, size_t offset) {
  return std::string(turf::ErrorName(error)) + " at byte " + std::to_string(offset);
}

// For a decoder whose message keeps a list of issues (any struct of an error and a detail text): the expressions
// of `text`, or none and one issue kParse, SExprErrorAt(the parser's error).
template <class Issue>
std::vector<SExpr> ParseSExprsOrIssue(std::string_view text, std::vector<Issue>* issues) {
  SExprParse parse = ParseSExprs(text);
  if (parse.error != turf::Error::kOk)
    issues->push_back({turf::Error::kParse, SExprErrorAt(parse.error, parse.offset)});
  return std::move(parse.exprs);
}

// Atom helpers shared by the decoders. Numbers are decimal only ([+-]digits[.digits][e[+-]digits]),
// the whole atom must be the number: "1.0abc", "0x10", "" and " 1" are bad.
enum class NumberError { kOk, kBad, kNotFinite };  // kNotFinite: nan, inf, infinity (any case), or overflow
NumberError ParseDouble(std::string_view atom, double* out);
// A decimal integer without fraction or exponent, within int range.
bool ParseInt(std::string_view atom, int* out);

}  // namespace turf::simspark
