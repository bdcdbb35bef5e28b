#include "codecs/rcssservermj/actions.h"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>

#include "codecs/simspark/sexpr.h"

namespace turf::rcssservermj {

namespace {

using simspark::NumberError;
using simspark::SExpr;

constexpr double kRad = M_PI / 180.0;

// The numbers of `e` after its head, all finite; the error otherwise.
turf::Error Numbers(const SExpr& e, size_t count, double* out) {
  if (e.items.size() != count + 1) return turf::Error::kBadArguments;
  for (size_t i = 0; i < count; ++i) {
    if (e.items[i + 1].is_list) return turf::Error::kBadArguments;
    const NumberError n = simspark::ParseDouble(e.items[i + 1].atom, &out[i]);
    if (n == NumberError::kNotFinite) return turf::Error::kNotFinite;
    if (n != NumberError::kOk) return turf::Error::kBadArguments;
  }
  return turf::Error::kOk;
}

turf::Error Motor(const SExpr& e, const MjRobotModel& model, MotorAction* out) {
  const int joint = EffectorIndex(model, e.Head());
  if (joint < 0) return turf::Error::kUnknownEffector;
  double v[5];
  if (const turf::Error error = Numbers(e, 5, v); error != turf::Error::kOk) return error;
  if (std::abs(v[0]) > kMaxAbsQDeg || std::abs(v[1]) > kMaxAbsDqDegS || v[2] < 0 || v[2] > kMaxKp || v[3] < 0 ||
      v[3] > kMaxKd || std::abs(v[4]) > kMaxAbsTau)
    return turf::Error::kOutOfRange;
  *out = MotorAction{joint, v[0] * kRad, v[1] * kRad, v[2], v[3], v[4]};
  return turf::Error::kOk;
}

turf::Error Beam(const SExpr& e, BeamAction* out) {
  double v[3];
  if (const turf::Error error = Numbers(e, 3, v); error != turf::Error::kOk) return error;
  if (std::abs(v[0]) > kMaxAbsBeam || std::abs(v[1]) > kMaxAbsBeam) return turf::Error::kOutOfRange;
  *out = BeamAction{v[0], v[1], v[2]};
  return turf::Error::kOk;
}

}  // namespace

turf::Error ParseInit(std::string_view payload, InitAction* out) {
  const simspark::SExprParse parse = simspark::ParseSExprs(payload);
  if (parse.error != turf::Error::kOk) return turf::Error::kParse;
  if (parse.exprs.size() != 1) return turf::Error::kBadArguments;
  const SExpr& e = parse.exprs[0];
  if (!e.IsCall("init") || e.items.size() != 4) return turf::Error::kBadArguments;
  for (const SExpr& item : e.items)
    if (item.is_list) return turf::Error::kBadArguments;
  // The reference takes int(n): an integer atom; |n| mod 100.
  const std::string& n = e.items[3].atom;
  size_t digits = n.size();
  if (!n.empty() && (n[0] == '-' || n[0] == '+')) --digits;
  if (digits == 0 || digits > 18 || n.find_first_not_of("0123456789", n.size() - digits) != std::string::npos)
    return turf::Error::kBadArguments;
  const long long number = std::llabs(std::strtoll(n.c_str(), nullptr, 10));
  *out = InitAction{e.items[1].atom, e.items[2].atom, static_cast<int>(number % 100)};
  return turf::Error::kOk;
}

ActionMessage ParseActions(std::string_view payload, const MjRobotModel& model) {
  ActionMessage m;
  for (const SExpr& e : simspark::ParseSExprsOrIssue(payload, &m.issues)) {
    const std::string_view head = e.Head();
    auto refuse = [&](turf::Error error) {
      m.issues.push_back({error, fmt::format("({} ...): {}", head.substr(0, 32), turf::ErrorName(error))});
    };
    if (head == "syn") {
      m.syn = true;
    } else if (head == "init") {
      refuse(turf::Error::kNotAllowed);  // only as the first message
    } else if (head == "say") {
      m.say = true;
    } else if (head == "beam") {
      BeamAction beam;
      const turf::Error error = Beam(e, &beam);
      if (error == turf::Error::kOk) {
        m.beam = beam;
      } else {
        refuse(error);
      }
    } else if (e.items.size() == 6 && !head.empty()) {
      MotorAction motor;
      const turf::Error error = Motor(e, model, &motor);
      if (error == turf::Error::kOk) {
        m.motors.push_back(motor);
      } else {
        refuse(error);
      }
    } else {
      refuse(head.empty() ? turf::Error::kMalformed : turf::Error::kUnknownEffector);
    }
  }
  return m;
}

}  // namespace turf::rcssservermj
