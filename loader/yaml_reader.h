// Reading untrusted YAML into typed values. Every problem (wrong type, not
// finite, unknown or duplicate key) becomes an error that names the key path
// and line; nothing here throws on bad input. Shared by the scene, legged scene
// and realism readers, with what every kind of scene file reads the same way.
#pragma once

#include <yaml-cpp/yaml.h>

#include <cstddef>
#include <cstdint>
#include <exception>
#include <functional>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "loader/text_file.h"

namespace turf::yaml {

using Errors = std::vector<std::string>;

// "path: what (line n)"; the line is left out when the node has no position.
std::string Message(const std::string& path, const YAML::Node& where, const std::string& what);

// Scalar readers: write *out and return true, or append an error naming
// `path` and return false. Numbers must be finite, plain (unquoted) scalars.
bool ReadNumber(const YAML::Node& node, const std::string& path, Errors* errors, double* out);
bool ReadInt(const YAML::Node& node, const std::string& path, Errors* errors, int* out);
bool ReadUint64(const YAML::Node& node, const std::string& path, Errors* errors, uint64_t* out);
bool ReadBool(const YAML::Node& node, const std::string& path, Errors* errors, bool* out);
bool ReadString(const YAML::Node& node, const std::string& path, Errors* errors, std::string* out);
// A list of exactly `count` numbers; *out is written only when all are valid.
bool ReadNumbers(const YAML::Node& node, const std::string& path, Errors* errors, double* out, size_t count);

// One YAML map with a fixed set of keys. Each read names a key, marks it as
// known and leaves *out untouched when the key is absent (the default stays).
// Finish() reports every key nobody asked for, so typos never pass silently.
// A null node (an empty section) reads as an empty map.
class MapReader {
 public:
  MapReader(const YAML::Node& node, std::string path, Errors* errors);

  bool Has(const std::string& key);
  bool Number(const std::string& key, double* out);
  // Reads `key` (which ends in _deg) in degrees and writes radians.
  bool Degrees(const std::string& key, double* radians);
  bool Int(const std::string& key, int* out);
  bool Uint64(const std::string& key, uint64_t* out);
  bool Bool(const std::string& key, bool* out);
  bool String(const std::string& key, std::string* out);
  bool Numbers(const std::string& key, double* out, size_t count);
  // A list of two numbers [x, y]; *x and *y are written only when both are valid.
  bool Point(const std::string& key, double* x, double* y);
  // A nested map; absent reads as empty.
  MapReader Map(const std::string& key);
  // The raw value of `key` (a null node when absent), for lists.
  YAML::Node Child(const std::string& key);
  // Each map of the list `key`, handed to `read` as a MapReader at "<path>.<key>[i]"; absent or null: none. Anything
  // but a list is an error "expected <what>".
  void EachMap(const std::string& key, const std::string& what, const std::function<void(MapReader)>& read);

  const std::string& path() const { return path_; }
  Errors* errors() const { return errors_; }
  std::string PathOf(const std::string& key) const;
  // An error at `key` (at this map when the key is absent).
  void Fail(const std::string& key, const std::string& what);
  // Reports unknown keys; call after all reads.
  void Finish();

 private:
  struct Entry {
    std::string key;
    YAML::Node key_node;
    YAML::Node value;
  };
  // Both mark `key` as known; nullptr when absent (LeafValue: or without a value).
  const Entry* Find(const std::string& key);
  const YAML::Node* LeafValue(const std::string& key);

  YAML::Node node_;  // the map itself, to place errors about absent keys
  std::string path_;
  Errors* errors_;
  std::vector<Entry> entries_;
  std::set<std::string> known_;
};

// The one document of a scene file, when it is a map; otherwise nullopt and an
// error (malformed YAML at its line and column, several documents, not a map).
std::optional<YAML::Node> LoadSceneDocument(const std::string& text, Errors* errors);

// physics: the step (s) and the solver's iterations, alike in every kind of scene; `extra(m)` reads a kind's own
// keys before the map is finished.
template <class Physics, class Extra>
void ReadPhysics(MapReader m, Physics* p, Extra extra) {
  m.Number("step", &p->step);
  m.Int("solver_iterations", &p->solver_iterations);
  extra(m);
  m.Finish();
}
template <class Physics>
void ReadPhysics(MapReader m, Physics* p) {
  ReadPhysics(m, p, [](MapReader&) {});
}

// `parse()` (a scene's parse); an exception yaml-cpp throws on input nobody
// foresaw becomes the error "cannot read the scene: ...": report, never crash.
template <class Result, class Parse>
Result ParseGuarded(Parse parse) {
  try {
    return parse();
  } catch (const std::exception& e) {
    Result result;
    result.errors.push_back("cannot read the scene: " + std::string(e.what()));
    return result;
  }
}

// Reads the file at `path` (at most `max_bytes`) and `parse(text)`s it; every
// error, a file that cannot be read included, starts with the path.
template <class Result, class Parse>
Result LoadFile(const std::string& path, uintmax_t max_bytes, Parse parse) {
  Result result;
  std::string text;
  std::string error;
  try {
    if (ReadTextFile(path, max_bytes, &text, &error)) {
      result = parse(text);
    } else {
      result.errors.push_back(error);
    }
  } catch (const std::exception& e) {
    result.scene.reset();
    result.errors.push_back("cannot read: " + std::string(e.what()));
  }
  for (std::string& message : result.errors) message = path + ": " + message;
  return result;
}

}  // namespace turf::yaml
