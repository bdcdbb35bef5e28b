// Flag checks whose refusal says what is allowed in a line a person reads (CLI11's own NonNegativeNumber prints
// the largest double, about 310 digits). Header-only: every executable with CLI11 uses it.
#pragma once

#include <CLI/CLI.hpp>

#include <cmath>
#include <string>

namespace turf {

// A finite number >= 0 (or > 0 when `zero_allowed` is false).
inline CLI::Validator FiniteAtLeastZero(bool zero_allowed = true) {
  const std::string rule = zero_allowed ? "a number >= 0" : "a number > 0";
  return CLI::Validator(
      [zero_allowed, rule](std::string& text) -> std::string {
        double v = 0.0;
        if (!CLI::detail::lexical_cast(text, v) || !std::isfinite(v) || v < 0.0 || (!zero_allowed && v == 0.0))
          return "'" + text + "' is not " + rule;
        return "";
      },
      zero_allowed ? "NUMBER >= 0" : "NUMBER > 0");
}

}  // namespace turf
