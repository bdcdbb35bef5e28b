#include "bridges/simspark/perception.h"

#include <cmath>
#include <cstdint>
#include <cstdio>

namespace turf::simspark {

void AppendFloat(std::string* out, double v) {
  if (!std::isfinite(v)) {
    out->append("0.00");
    return;
  }
  // The common case without printf (a perception has ~150 numbers); printf
  // for huge values.
  if (std::abs(v) < 1e12) {
    // The exact product a * 100 against c + 0.5, by fma, so near-ties round
    // like printf (which rounds the exact binary value, ties to even).
    const double a = std::abs(v);
    double c = std::floor(a * 100.0);
    if (std::fma(a, 100.0, -c) < 0) c -= 1.0;
    const double above_half = std::fma(a, 100.0, -(c + 0.5));
    if (above_half > 0 || (above_half == 0 && std::fmod(c, 2.0) != 0)) c += 1.0;
    const auto hundredths = static_cast<int64_t>(c);
    char digits[24];
    int n = 0;
    int64_t whole = hundredths / 100;
    do {
      digits[n++] = static_cast<char>('0' + whole % 10);
      whole /= 10;
    } while (whole > 0);
    if (std::signbit(v)) out->push_back('-');
    while (n > 0) out->push_back(digits[--n]);
    out->push_back('.');
    out->push_back(static_cast<char>('0' + (hundredths % 100) / 10));
    out->push_back(static_cast<char>('0' + hundredths % 10));
    return;
  }
  out->append(FormatFloat(v));
}

std::string FormatFloat(double v) {
  if (!std::isfinite(v)) return "0.00";
  if (std::abs(v) < 1e12) {
    std::string out;
    AppendFloat(&out, v);
    return out;
  }
  char buffer[32];
  const int n = std::snprintf(buffer, sizeof(buffer), "%.2f", v);
  if (n >= 0 && static_cast<size_t>(n) < sizeof(buffer)) return std::string(buffer, static_cast<size_t>(n));
  std::string big(static_cast<size_t>(n) + 1, '\0');  // |v| >= 1e29: rare, but printed whole
  std::snprintf(big.data(), big.size(), "%.2f", v);
  big.resize(static_cast<size_t>(n));
  return big;
}

namespace {

void Append3(std::string* out, const std::array<double, 3>& v) {
  for (const double x : v) {
    out->push_back(' ');
    AppendFloat(out, x);
  }
}

void AppendPol(std::string* out, const Polar& p) {
  out->append("(pol ");
  AppendFloat(out, p.distance);
  out->push_back(' ');
  AppendFloat(out, p.horizontal);
  out->push_back(' ');
  AppendFloat(out, p.vertical);
  out->push_back(')');
}

std::string FormatSee(const SeeItems& see) {
  std::string out = "(See";
  for (const SeeObject& o : see.objects) {
    out += " (" + o.label + ' ';
    AppendPol(&out, o.pol);
    out.push_back(')');
  }
  for (const SeePlayer& player : see.players) {
    out += " (P (team " + player.team + ") (id " + std::to_string(player.id) + ')';
    for (const SeePart& part : player.parts) {
      out += " (" + part.name + ' ';
      AppendPol(&out, part.pol);
      out.push_back(')');
    }
    out.push_back(')');
  }
  for (const SeeLine& line : see.lines) {
    out += " (L ";
    AppendPol(&out, line.begin);
    out.push_back(' ');
    AppendPol(&out, line.end);
    out.push_back(')');
  }
  out.push_back(')');
  return out;
}

std::string FormatHear(const Heard& heard) {
  return "(hear " + heard.team + ' ' + FormatFloat(heard.game_time) + ' ' +
         (heard.self ? std::string("self") : FormatFloat(heard.direction)) + ' ' + heard.message + ')';
}

}  // namespace

std::string FormatPerception(const Perception& p) {
  std::string out;
  out.reserve(1024);
  out += "(time (now " + FormatFloat(p.time) + "))";
  out += "(GS";
  if (p.unum) out += " (unum " + std::to_string(*p.unum) + ')';
  if (p.side) out += std::string(" (team ") + SideName(*p.side) + ')';
  out += " (sl " + std::to_string(p.score_left) + ") (sr " + std::to_string(p.score_right) + ") (t " +
         FormatFloat(p.game_time) + ") (pm " + PlayModeName(p.play_mode) + "))";
  out += "(GYR (n torso) (rt";
  Append3(&out, p.gyro_deg_s);
  out += "))(ACC (n torso) (a";
  Append3(&out, p.acc);
  out += "))";
  for (const auto& [name, deg] : p.joints_deg) {
    out += "(HJ (n ";
    out += name;
    out += ") (ax ";
    AppendFloat(&out, deg);
    out += "))";
  }
  for (const ForcePerception& f : p.forces) {
    out += "(FRP (n " + f.name + ") (c";
    Append3(&out, f.point);
    out += ") (f";
    Append3(&out, f.force);
    out += "))";
  }
  if (p.see) out += FormatSee(*p.see);
  for (const Heard& heard : p.heard) out += FormatHear(heard);
  return out;
}

}  // namespace turf::simspark
