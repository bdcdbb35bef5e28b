// Team colours in rendered images: a robot whose scene name says its team (red_1, blue_3, yellow2, "Blue-1": the
// name, case aside, starts with red, blue or yellow followed by its end, a digit, '_' or '-') has its trunk (the
// geoms of its top-level body) drawn in that colour, as a jersey; other robots keep their files' colours. Pure.
#pragma once

#include <array>
#include <optional>
#include <string>

namespace turf {

// RGBA of the team the name says, or none.
std::optional<std::array<float, 4>> TeamColour(const std::string& robot);

}  // namespace turf
