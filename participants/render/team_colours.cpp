#include "participants/render/team_colours.h"

#include <cctype>

namespace turf {

std::optional<std::array<float, 4>> TeamColour(const std::string& robot) {
  struct Team {
    const char* name;
    std::array<float, 4> rgba;
  };
  static const Team kTeams[] = {{"red", {0.85f, 0.08f, 0.08f, 1.0f}},
                                {"blue", {0.08f, 0.2f, 0.9f, 1.0f}},
                                {"yellow", {0.95f, 0.85f, 0.08f, 1.0f}}};
  std::string lower;
  for (char c : robot) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (const Team& t : kTeams) {
    const std::string n = t.name;
    if (lower.compare(0, n.size(), n) != 0) continue;
    if (lower.size() == n.size()) return t.rgba;
    const unsigned char next = static_cast<unsigned char>(lower[n.size()]);
    if (std::isdigit(next) || next == '_' || next == '-') return t.rgba;
  }
  return std::nullopt;
}

}  // namespace turf
