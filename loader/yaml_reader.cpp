#include "loader/yaml_reader.h"

#include <fmt/format.h>
#include <yaml-cpp/eventhandler.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <sstream>
#include <system_error>

namespace turf::yaml {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr size_t kMaxShownScalar = 40;

std::string Describe(const YAML::Node& node) {
  switch (node.Type()) {
    case YAML::NodeType::Scalar: {
      std::string text = node.Scalar();
      if (text.size() > kMaxShownScalar) text = text.substr(0, kMaxShownScalar - 3) + "...";
      return fmt::format("\"{}\"", text);
    }
    case YAML::NodeType::Sequence:
      return "a list";
    case YAML::NodeType::Map:
      return "a map";
    default:
      return "nothing";
  }
}

// Quoted ("3") or explicitly tagged (!!str 3) scalars are text, never numbers.
bool IsText(const YAML::Node& node) { return node.Tag() == "!" || node.Tag() == "tag:yaml.org,2002:str"; }

enum class Parsed { kOk, kInvalid, kOutOfRange };

// Parses the whole of `text` (an optional leading '+' allowed) as a T.
template <typename T>
Parsed ParseWhole(std::string_view text, T* out) {
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  if (text.empty()) return Parsed::kInvalid;
  const char* end = text.data() + text.size();
  std::from_chars_result result;
  if constexpr (std::is_floating_point_v<T>) {
    result = std::from_chars(text.data(), end, *out, std::chars_format::general);
  } else {
    result = std::from_chars(text.data(), end, *out, 10);
  }
  if (result.ec == std::errc::result_out_of_range) return Parsed::kOutOfRange;
  if (result.ec != std::errc() || result.ptr != end) return Parsed::kInvalid;
  return Parsed::kOk;
}

// YAML's spellings of infinity and not-a-number (.inf, -.Inf, .NaN, ...).
bool IsYamlNonFinite(std::string text) {
  if (!text.empty() && (text.front() == '+' || text.front() == '-')) text.erase(0, 1);
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
  return text == ".inf" || text == ".nan";
}

template <typename T>
bool ReadInteger(const YAML::Node& node, const std::string& path, Errors* errors, const char* expected, T* out) {
  if (!node.IsScalar() || IsText(node)) {
    errors->push_back(Message(path, node, fmt::format("expected {}, got {}", expected, Describe(node))));
    return false;
  }
  T value{};
  switch (ParseWhole(node.Scalar(), &value)) {
    case Parsed::kOk:
      *out = value;
      return true;
    case Parsed::kOutOfRange:
      errors->push_back(Message(path, node, fmt::format("{} is out of range", Describe(node))));
      return false;
    default:
      errors->push_back(Message(path, node, fmt::format("expected {}, got {}", expected, Describe(node))));
      return false;
  }
}

size_t EditDistance(const std::string& a, const std::string& b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diagonal = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

}  // namespace

std::string Message(const std::string& path, const YAML::Node& where, const std::string& what) {
  const YAML::Mark mark = where.Mark();
  if (mark.is_null()) return fmt::format("{}: {}", path, what);
  return fmt::format("{}: {} (line {})", path, what, mark.line + 1);
}

bool ReadNumber(const YAML::Node& node, const std::string& path, Errors* errors, double* out) {
  if (!node.IsScalar() || IsText(node)) {
    const char* quoted = node.IsScalar() ? "the quoted text " : "";
    errors->push_back(Message(path, node, fmt::format("expected a number, got {}{}", quoted, Describe(node))));
    return false;
  }
  double value = 0.0;
  const Parsed parsed = ParseWhole(node.Scalar(), &value);
  if (IsYamlNonFinite(node.Scalar()) || parsed == Parsed::kOutOfRange ||
      (parsed == Parsed::kOk && !std::isfinite(value))) {
    errors->push_back(Message(path, node, fmt::format("expected a finite number, got {}", Describe(node))));
    return false;
  }
  if (parsed != Parsed::kOk) {
    errors->push_back(Message(path, node, fmt::format("expected a number, got {}", Describe(node))));
    return false;
  }
  *out = value;
  return true;
}

bool ReadInt(const YAML::Node& node, const std::string& path, Errors* errors, int* out) {
  return ReadInteger(node, path, errors, "an integer", out);
}

bool ReadUint64(const YAML::Node& node, const std::string& path, Errors* errors, uint64_t* out) {
  return ReadInteger(node, path, errors, "a non-negative integer", out);
}

bool ReadBool(const YAML::Node& node, const std::string& path, Errors* errors, bool* out) {
  if (node.IsScalar() && !IsText(node)) {
    const std::string& text = node.Scalar();
    if (text == "true" || text == "True" || text == "TRUE") {
      *out = true;
      return true;
    }
    if (text == "false" || text == "False" || text == "FALSE") {
      *out = false;
      return true;
    }
  }
  errors->push_back(Message(path, node, fmt::format("expected true or false, got {}", Describe(node))));
  return false;
}

bool ReadString(const YAML::Node& node, const std::string& path, Errors* errors, std::string* out) {
  if (!node.IsScalar()) {
    errors->push_back(Message(path, node, fmt::format("expected text, got {}", Describe(node))));
    return false;
  }
  *out = node.Scalar();
  return true;
}

bool ReadNumbers(const YAML::Node& node, const std::string& path, Errors* errors, double* out, size_t count) {
  if (!node.IsSequence() || node.size() != count) {
    const std::string got = node.IsSequence() ? fmt::format("a list of {}", node.size()) : Describe(node);
    errors->push_back(Message(path, node, fmt::format("expected a list of {} numbers, got {}", count, got)));
    return false;
  }
  std::vector<double> values(count);
  bool ok = true;
  size_t i = 0;
  for (const YAML::Node& item : node) {
    ok = ReadNumber(item, fmt::format("{}[{}]", path, i), errors, &values[i]) && ok;
    ++i;
  }
  if (ok) std::copy(values.begin(), values.end(), out);
  return ok;
}

MapReader::MapReader(const YAML::Node& node, std::string path, Errors* errors)
    : node_(node), path_(std::move(path)), errors_(errors) {
  if (!node.IsDefined() || node.IsNull()) return;
  if (!node.IsMap()) {
    errors_->push_back(Message(path_, node, fmt::format("expected a map, got {}", Describe(node))));
    return;
  }
  std::set<std::string> seen;  // a file's keys are many at most in a crafted one: no scan of them all per key
  for (const auto& pair : node) {
    if (!pair.first.IsScalar()) {
      errors_->push_back(
          Message(path_, pair.first, fmt::format("expected a name as key, got {}", Describe(pair.first))));
      continue;
    }
    const std::string& key = pair.first.Scalar();
    if (!seen.insert(key).second) {
      errors_->push_back(Message(PathOf(key), pair.first, "duplicate key"));
      continue;
    }
    entries_.push_back({key, pair.first, pair.second});
  }
}

const MapReader::Entry* MapReader::Find(const std::string& key) {
  known_.insert(key);
  for (const Entry& entry : entries_) {
    if (entry.key == key) return &entry;
  }
  return nullptr;
}

bool MapReader::Has(const std::string& key) { return Find(key) != nullptr; }

// A leaf key written without a value ("max_speed:") is an error, not a default.
const YAML::Node* MapReader::LeafValue(const std::string& key) {
  const Entry* e = Find(key);
  if (!e) return nullptr;
  if (e->value.IsNull()) {
    errors_->push_back(Message(PathOf(key), e->key_node, "no value given"));
    return nullptr;
  }
  return &e->value;
}

bool MapReader::Number(const std::string& key, double* out) {
  const YAML::Node* value = LeafValue(key);
  return value && ReadNumber(*value, PathOf(key), errors_, out);
}

bool MapReader::Degrees(const std::string& key, double* radians) {
  double degrees = 0.0;
  if (!Number(key, &degrees)) return false;
  *radians = degrees * kPi / 180.0;
  return true;
}

bool MapReader::Int(const std::string& key, int* out) {
  const YAML::Node* value = LeafValue(key);
  return value && ReadInt(*value, PathOf(key), errors_, out);
}

bool MapReader::Uint64(const std::string& key, uint64_t* out) {
  const YAML::Node* value = LeafValue(key);
  return value && ReadUint64(*value, PathOf(key), errors_, out);
}

bool MapReader::Bool(const std::string& key, bool* out) {
  const YAML::Node* value = LeafValue(key);
  return value && ReadBool(*value, PathOf(key), errors_, out);
}

bool MapReader::String(const std::string& key, std::string* out) {
  const YAML::Node* value = LeafValue(key);
  return value && ReadString(*value, PathOf(key), errors_, out);
}

bool MapReader::Numbers(const std::string& key, double* out, size_t count) {
  const YAML::Node* value = LeafValue(key);
  return value && ReadNumbers(*value, PathOf(key), errors_, out, count);
}

MapReader MapReader::Map(const std::string& key) { return MapReader(Child(key), PathOf(key), errors_); }

YAML::Node MapReader::Child(const std::string& key) {
  const Entry* e = Find(key);
  return e ? e->value : YAML::Node();
}

bool MapReader::Point(const std::string& key, double* x, double* y) {
  double xy[2] = {*x, *y};
  if (!Numbers(key, xy, 2)) return false;
  *x = xy[0];
  *y = xy[1];
  return true;
}

void MapReader::EachMap(const std::string& key, const std::string& what, const std::function<void(MapReader)>& read) {
  const YAML::Node list = Child(key);
  if (!list.IsDefined() || list.IsNull()) return;
  if (!list.IsSequence()) {
    Fail(key, "expected " + what);
    return;
  }
  for (size_t i = 0; i < list.size(); ++i) read(MapReader(list[i], fmt::format("{}[{}]", PathOf(key), i), errors_));
}

std::string MapReader::PathOf(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }

void MapReader::Fail(const std::string& key, const std::string& what) {
  // Never assign to a YAML::Node that refers to a node: that rewrites the tree.
  const auto it = std::find_if(entries_.begin(), entries_.end(), [&key](const Entry& e) { return e.key == key; });
  errors_->push_back(Message(PathOf(key), it != entries_.end() ? it->key_node : node_, what));
}

void MapReader::Finish() {
  for (const Entry& entry : entries_) {
    if (known_.count(entry.key)) continue;
    std::string what = "unknown key";
    // Suggest only near misses: a few edits, fewer than the words have letters.
    size_t best = std::max<size_t>(2, entry.key.size() / 4) + 1;
    for (const std::string& candidate : known_) {
      const size_t distance = EditDistance(entry.key, candidate);
      if (distance < best && distance < std::min(entry.key.size(), candidate.size())) {
        best = distance;
        what = fmt::format("unknown key (did you mean {}?)", candidate);
      }
    }
    errors_->push_back(Message(PathOf(entry.key), entry.key_node, what));
  }
}

namespace {

// Where each YAML document of a text starts, and nothing else.
class DocumentStarts final : public YAML::EventHandler {
 public:
  const std::vector<YAML::Mark>& starts() const { return starts_; }
  // yaml-cpp 0.7 yields an empty document without consuming the token at a document's start that cannot begin
  // one (a ','), again and again: its LoadAll never returns there. A document starting where the one before it
  // started is that.
  bool Stuck() const { return starts_.size() >= 2 && starts_.back().pos == starts_[starts_.size() - 2].pos; }

  void OnDocumentStart(const YAML::Mark& mark) override { starts_.push_back(mark); }
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark&, YAML::anchor_t) override {}
  void OnAlias(const YAML::Mark&, YAML::anchor_t) override {}
  void OnScalar(const YAML::Mark&, const std::string&, YAML::anchor_t, const std::string&) override {}
  void OnSequenceStart(const YAML::Mark&, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override {}
  void OnSequenceEnd() override {}
  void OnMapStart(const YAML::Mark&, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override {}
  void OnMapEnd() override {}

 private:
  std::vector<YAML::Mark> starts_;
};

}  // namespace

// The documents are counted by a parser of our own loop (not YAML::LoadAll, see DocumentStarts), then the one
// document is loaded.
std::optional<YAML::Node> LoadSceneDocument(const std::string& text, Errors* errors) {
  DocumentStarts documents;
  YAML::Node root;
  try {
    std::istringstream in(text);
    YAML::Parser parser(in);
    while (parser.HandleNextDocument(documents)) {
      if (!documents.Stuck()) continue;
      const YAML::Mark& at = documents.starts().back();
      errors->push_back(
          fmt::format("malformed YAML at line {}, column {}: no document can start here", at.line + 1, at.column + 1));
      return std::nullopt;
    }
    if (documents.starts().size() == 1) root = YAML::Load(text);
  } catch (const YAML::ParserException& e) {
    errors->push_back(
        fmt::format("malformed YAML at line {}, column {}: {}", e.mark.line + 1, e.mark.column + 1, e.msg));
    return std::nullopt;
  }
  const size_t count = documents.starts().size();
  if (count != 1 || !root.IsMap()) {
    errors->push_back(count > 1 ? fmt::format("expected one YAML document, got {}", count)
                                : "expected a map of scene settings at the top level");
    return std::nullopt;
  }
  return root;
}

}  // namespace turf::yaml
