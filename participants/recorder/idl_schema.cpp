#include "participants/recorder/idl_schema.h"

#include <set>
#include <sstream>

namespace turf::record {
namespace {

const IdlFile* Find(std::string_view name) {
  for (const IdlFile& f : IdlFiles())
    if (name == f.name) return &f;
  return nullptr;
}

// `file`'s text after the files it includes (each once: `done`), without the #include lines.
void Resolve(const IdlFile& file, std::set<std::string>* done, std::string* out) {
  if (!done->insert(file.name).second) return;
  std::istringstream lines(file.text);
  std::string body;
  for (std::string line; std::getline(lines, line);) {
    const size_t open = line.find("#include \"");
    if (open != 0) {
      // Other preprocessor lines (include guards) are dropped: the schema is one text, each file in it once.
      if (line.find_first_not_of(" \t") == std::string::npos || line[line.find_first_not_of(" \t")] != '#')
        body += line + "\n";
      continue;
    }
    const size_t start = open + 10;
    const size_t close = line.find('"', start);
    const IdlFile* included = close == std::string::npos ? nullptr : Find(line.substr(start, close - start));
    if (included != nullptr) Resolve(*included, done, out);
  }
  *out += "// ---- " + std::string(file.name) + "\n" + body;
}

}  // namespace

std::string IdlSchema(std::string_view type) {
  const std::string needle = "struct " + std::string(type);
  for (const IdlFile& f : IdlFiles()) {
    const std::string_view text(f.text);
    for (size_t at = text.find(needle); at != std::string_view::npos; at = text.find(needle, at + 1)) {
      const char next = at + needle.size() < text.size() ? text[at + needle.size()] : '\0';
      if (next != ' ' && next != '{' && next != '\n') continue;  // "struct ClockX" is not "struct Clock"
      std::set<std::string> done;
      std::string out;
      Resolve(f, &done, &out);
      return out;
    }
  }
  return {};
}

}  // namespace turf::record
