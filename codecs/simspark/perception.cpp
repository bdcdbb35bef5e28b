#include "codecs/simspark/perception.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>

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

// Every number of a perceptor is a single-precision float in the reference
// (salt::Vector3f, HingeJoint::GetAngle, SimulationServer::GetTime and the
// game's TTime are float) and its stream prints that float: round to float
// first so that near-ties round as the reference's do. Beyond float's range
// the value saturates at the largest float (the reference would overflow to
// inf), so no number is longer than 42 characters for an agent's parser.
void AppendWire(std::string* out, double v) {
  constexpr double kMax = std::numeric_limits<float>::max();
  if (std::isfinite(v)) v = static_cast<float>(std::clamp(v, -kMax, kMax));
  AppendFloat(out, v);
}

void Append3(std::string* out, const std::array<double, 3>& v) {
  for (const double x : v) {
    out->push_back(' ');
    AppendWire(out, x);
  }
}

void AppendPol(std::string* out, const Polar& p) {
  out->append("(pol ");
  AppendWire(out, p.distance);
  out->push_back(' ');
  AppendWire(out, p.horizontal);
  out->push_back(' ');
  AppendWire(out, p.vertical);
  out->push_back(')');
}

// The reference's SexpParser::PredicateToString writes a perceptor as '(',
// its name, one space, the parameters separated by one space, ')'. The space
// after the name is written even when there are no parameters: an empty See
// (RestrictedVisionPerceptor::DynamicAxisPercept always adds the predicate)
// is "(See )", never "(See)". Sub-lists never have that space.
void AppendSee(std::string* out, const SeeItems& see) {
  out->append("(See ");
  const char* separator = "";
  for (const SeeObject& o : see.objects) {
    *out += separator;
    *out += '(' + o.label + ' ';
    AppendPol(out, o.pol);
    out->push_back(')');
    separator = " ";
  }
  for (const SeePlayer& player : see.players) {
    *out += separator;
    *out += "(P (team " + player.team + ") (id " + std::to_string(player.id) + ')';
    for (const SeePart& part : player.parts) {
      *out += " (" + part.name + ' ';
      AppendPol(out, part.pol);
      out->push_back(')');
    }
    out->push_back(')');
    separator = " ";
  }
  for (const SeeLine& line : see.lines) {
    *out += separator;
    out->append("(L ");
    AppendPol(out, line.begin);
    out->push_back(' ');
    AppendPol(out, line.end);
    out->push_back(')');
    separator = " ";
  }
  out->push_back(')');
}

// HearPerceptor::Percept: `(hear <team> <t> self|<direction> <msg>)`.
void AppendHear(std::string* out, const Heard& heard) {
  *out += "(hear " + heard.team + ' ';
  AppendWire(out, heard.game_time);
  out->push_back(' ');
  if (heard.self) {
    out->append("self");
  } else {
    AppendWire(out, heard.direction);
  }
  *out += ' ' + heard.message + ')';
}

void AppendForce(std::string* out, const ForcePerception& f) {
  *out += "(FRP (n " + f.name + ") (c";
  Append3(out, f.point);
  out->append(") (f");
  Append3(out, f.force);
  out->append("))");
}

// The hinge of the body that carries a foot's FRP (naoleg.rsg / naolegtoe.rsg:
// the ForceResistancePerceptor is the first child of the foot (toe) transform,
// the hinge joint rlj6/llj6 (rlj7/llj7) comes after it), so the FRP is written
// just before that HJ. Empty for other names.
std::string HingeAfterFoot(const std::string& foot) {
  if (foot == "rf" || foot == "lf") return foot.substr(0, 1) + "lj6";
  if (foot == "rf1" || foot == "lf1") return foot.substr(0, 1) + "lj7";
  return {};
}

}  // namespace

std::string FormatPerception(const Perception& p) {
  std::string out;
  out.reserve(1024);
  // The order is the reference's: AgentAspect::QueryPerceptors asks the
  // perceptors in depth-first scene-graph order of nao_hetero.rsg: TimePerceptor,
  // GameStatePerceptor, HearPerceptor (both under AgentState), GyroRatePerceptor,
  // Accelerometer, then the head (hj1, hj2, RestrictedVisionPerceptor), the arms
  // and the legs (..., lj5, FRP, lj6[, FRP toe, lj7]).
  out += "(time (now ";  // TimePerceptor::Percept
  AppendWire(&out, p.time);
  out += "))";
  // GameStatePerceptor::Percept: unum and team only in the first GS after the
  // agent has a team; sl and sr always (ReportScore is true in naosoccersim.rb);
  // then t and pm. Scores and unum are ints.
  out += "(GS ";
  if (p.unum) out += "(unum " + std::to_string(*p.unum) + ") ";
  if (p.side) out += std::string("(team ") + SideName(*p.side) + ") ";
  out += "(sl " + std::to_string(p.score_left) + ") (sr " + std::to_string(p.score_right) + ") (t ";
  AppendWire(&out, p.game_time);
  out += std::string(") (pm ") + PlayModeName(p.play_mode) + "))";
  // No hear predicate at all when nothing is heard (HearPerceptor::Percept adds one per message).
  for (const Heard& heard : p.heard) AppendHear(&out, heard);
  out += "(GYR (n torso) (rt";
  Append3(&out, p.gyro_deg_s);
  out += "))(ACC (n torso) (a";
  Append3(&out, p.acc);
  out += "))";
  // FRP only while touching (ForceResistancePerceptor::Percept returns without a predicate on no contact).
  std::vector<bool> force_written(p.forces.size(), false);
  bool see_written = !p.see.has_value();
  for (const auto& [name, deg] : p.joints_deg) {
    for (size_t i = 0; i < p.forces.size(); ++i) {
      if (!force_written[i] && HingeAfterFoot(p.forces[i].name) == name) {
        AppendForce(&out, p.forces[i]);
        force_written[i] = true;
      }
    }
    out += "(HJ (n ";
    out += name;
    out += ") (ax ";
    AppendWire(&out, deg);
    out += "))";
    if (!see_written && name == "hj2") {  // the vision perceptor follows hj2 under the head
      AppendSee(&out, *p.see);
      see_written = true;
    }
  }
  // Without those joints: the head's See first, then the feet, as in the scene graph.
  if (!see_written) AppendSee(&out, *p.see);
  for (size_t i = 0; i < p.forces.size(); ++i)
    if (!force_written[i]) AppendForce(&out, p.forces[i]);
  return out;
}

}  // namespace turf::simspark
