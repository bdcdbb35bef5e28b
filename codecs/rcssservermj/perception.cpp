#include "codecs/rcssservermj/perception.h"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string_view>

namespace turf::rcssservermj {

namespace {

constexpr double kDeg = 180.0 / M_PI;

void AppendName(std::string* out, const char* perceptor, const char* name) {
  out->append("(").append(perceptor).append(" (n ").append(name).append(") ");
}

void AppendNumbers(std::string* out, const char* key, const double* v, int n, int decimals) {
  out->append("(").append(key);
  for (int i = 0; i < n; ++i) {
    out->push_back(' ');
    AppendNumber(out, v[i], decimals);
  }
  out->append(")");
}

void AppendPolar(std::string* out, const SeenMarker& m) {
  const double v[3] = {m.pol.distance, m.pol.azimuth, m.pol.elevation};
  out->append("(").append(m.name).append(" ");
  AppendNumbers(out, "pol", v, 3, 2);
  out->append(")");
}

void AppendGameState(std::string* out, const GameStateReading& g) {
  out->append("(GS (t ").append(PythonFloat(g.play_time)).append(")(pm ").append(g.play_mode).append(")");
  if (g.team_left) out->append("(tl ").append(*g.team_left).append(")");
  if (g.team_right) out->append("(tr ").append(*g.team_right).append(")");
  out->append("(sl ").append(std::to_string(g.score_left)).append(")(sr ");
  out->append(std::to_string(g.score_right)).append("))");
}

void AppendSee(std::string* out, const SeeItems& see) {
  out->append("(See ");
  for (const SeenMarker& m : see.markers) AppendPolar(out, m);
  for (const SeenPlayer& p : see.players) {
    out->append("(P (team ").append(p.team).append(")(id ").append(std::to_string(p.number)).append(")");
    for (const SeenMarker& m : p.parts) AppendPolar(out, m);
    out->append(")");
  }
  out->append(")");
}

}  // namespace

std::string PythonFloat(double v) {
  if (!std::isfinite(v)) return "0.0";
  if (v == 0) return std::signbit(v) ? "-0.0" : "0.0";
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof(buffer), std::abs(v), std::chars_format::scientific);
  const std::string_view text(buffer, static_cast<size_t>(result.ptr - buffer));  // d[.ddd]e[+-]XX
  const size_t e = text.find('e');
  std::string digits;
  for (const char c : text.substr(0, e))
    if (c != '.') digits.push_back(c);
  const int exponent = std::atoi(std::string(text.substr(e + 1)).c_str());
  const int point = exponent + 1;  // value = 0.<digits> * 10^point
  const int n = static_cast<int>(digits.size());
  std::string out = v < 0 ? "-" : "";
  if (point > -4 && point <= 16) {  // Python's repr: fixed notation in this range
    if (point <= 0) {
      out.append("0.").append(static_cast<size_t>(-point), '0').append(digits);
    } else if (point >= n) {
      out.append(digits).append(static_cast<size_t>(point - n), '0').append(".0");
    } else {
      out.append(digits, 0, static_cast<size_t>(point)).append(".").append(digits, static_cast<size_t>(point));
    }
    return out;
  }
  out.push_back(digits[0]);
  if (n > 1) out.append(".").append(digits, 1);
  const int magnitude = std::abs(exponent);
  out.append(exponent < 0 ? "e-" : "e+");
  if (magnitude < 10) out.push_back('0');
  out.append(std::to_string(magnitude));
  return out;
}

double Truncate(double v, int decimals) {
  const double scale = std::pow(10.0, decimals);
  const double x = v * scale;
  // A decimal value whose binary form lies a hair below it (0.58 * 100 = 57.99999999999999) keeps its last digit:
  // so the time of cycle k reads exactly k * 0.02, never the same hundredth twice.
  const double nearest = std::round(x);
  const double whole = std::abs(x - nearest) < 1e-6 ? nearest : std::trunc(x);
  return std::copysign(whole / scale, v);
}

// The common case without PythonFloat's general path: Truncate's integer of hundredths or thousandths, written with
// the decimal point put in and trailing zeros dropped. That is Python's repr of the truncated double: below 1e15 the
// integer has at most 15 significant digits, so its decimal is the shortest that reads back as the same double, and
// 0.001 <= |value| < 1e16 is written in fixed notation. Tested against the general path.
void AppendNumber(std::string* out, double v, int decimals) {
  static constexpr double kScale[] = {1.0, 10.0, 100.0, 1000.0};  // std::pow(10, decimals), exactly
  const double x = decimals >= 0 && decimals <= 3 ? v * kScale[decimals] : NAN;
  if (!(std::abs(x) < 1e15)) {  // NaN, infinite, huge, or other decimals
    out->append(PythonFloat(Truncate(v, decimals)));
    return;
  }
  const double nearest = std::round(x);
  const double whole = std::abs(x - nearest) < 1e-6 ? nearest : std::trunc(x);  // as Truncate
  char digits[24];
  const auto written = std::to_chars(digits, digits + sizeof(digits), static_cast<uint64_t>(std::abs(whole)));
  std::string_view text(digits, static_cast<size_t>(written.ptr - digits));
  if (std::signbit(v)) out->push_back('-');  // the truncated value keeps v's sign, zero included (-0.0)
  if (whole == 0) {
    out->append("0.0");
    return;
  }
  const size_t d = static_cast<size_t>(decimals);
  if (text.size() <= d) {
    out->append("0.").append(d - text.size(), '0');
  } else {
    out->append(text.substr(0, text.size() - d)).push_back('.');
  }
  std::string_view fraction = text.size() <= d ? text : text.substr(text.size() - d);
  while (!fraction.empty() && fraction.back() == '0') fraction.remove_suffix(1);
  if (fraction.empty()) {
    out->push_back('0');
  } else {
    out->append(fraction);
  }
}

std::string FormatPerception(const MjPerception& p) {
  std::string out;
  out.reserve(2048);
  out.append("(time (now ");
  AppendNumber(&out, p.time, 2);
  out.append("))");
  AppendGameState(&out, p.game);
  if (!p.has_robot) return out;
  AppendName(&out, "quat", "torso_quat");
  AppendNumbers(&out, "q", p.quat.data(), 4, 3);
  out.append(")");
  AppendName(&out, "pos", "torso_pos");
  AppendNumbers(&out, "p", p.pos.data(), 3, 3);
  out.append(")");
  const double gyro_deg[3] = {p.gyro[0] * kDeg, p.gyro[1] * kDeg, p.gyro[2] * kDeg};
  AppendName(&out, "GYR", "torso_gyro");
  AppendNumbers(&out, "rt", gyro_deg, 3, 2);
  out.append(")");
  AppendName(&out, "ACC", "torso_acc");
  AppendNumbers(&out, "a", p.acc.data(), 3, 2);
  out.append(")");
  for (const JointReading& j : p.joints) {
    out.append("(HJ (n ").append(j.name).append(")(ax ");
    AppendNumber(&out, j.position * kDeg, 2);
    out.append(")(vx ");
    AppendNumber(&out, j.velocity * kDeg, 2);
    out.append("))");
  }
  if (p.see) AppendSee(&out, *p.see);
  return out;
}

}  // namespace turf::rcssservermj
