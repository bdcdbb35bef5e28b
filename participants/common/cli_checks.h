// Flag checks whose refusal says what is allowed in a line a person reads (CLI11's own NonNegativeNumber prints
// the largest double, about 310 digits). Header-only: every executable with CLI11 uses it.
#pragma once

#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "participants/common/address_allowlist.h"

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

// A port flag: 0..65535 (1..65535 unless `zero_allowed`), refused with the range it must be in
// ("--port: Value 99999 not in range 0 to 65535") rather than a bare conversion error. `port` must outlive parsing.
inline CLI::Option* AddPortOption(CLI::App& app, const std::string& name, uint16_t& port, const std::string& help,
                                  bool zero_allowed = false) {
  return app
      .add_option_function<int>(
          name, [&port](int value) { port = static_cast<uint16_t>(value); }, help)
      ->default_str(std::to_string(port))
      ->check(CLI::Range(zero_allowed ? 0 : 1, 65535));
}

// An allowlist entry, "ADDR" or "ADDR/PREFIX" (address_allowlist.h); `ipv4_only` for ports that listen on IPv4
// (an IPv6 entry there would never match, so it is refused rather than ignored).
inline CLI::Validator AddressRangeCheck(bool ipv4_only) {
  return CLI::Validator(
      [ipv4_only](std::string& text) -> std::string {
        std::string error;
        const std::optional<AddressRange> range = ParseAddressRange(text, &error);
        if (!range) return error;
        if (ipv4_only && range->v6) return "'" + text + "': these ports listen on IPv4; give an IPv4 address[/prefix]";
        return "";
      },
      "");
}

// A repeatable source allowlist flag of the SSL bridges' UDP ports (source_gate.h): IPv4 ranges, default anyone.
inline CLI::Option* AddAllowOption(CLI::App& app, const std::string& name, std::vector<std::string>& entries,
                                   const std::string& help) {
  return app.add_option(name, entries, help + "; repeatable or comma-separated; default: anyone (no check)")
      ->type_name("ADDR[/PREFIX]")
      ->delimiter(',')
      ->check(AddressRangeCheck(/*ipv4_only=*/true));
}

}  // namespace turf
