#include "codecs/rcssservermj/actions.h"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <string_view>

#include "codecs/simspark/sexpr.h"

namespace turf::rcssservermj {

namespace {

using simspark::NumberError;
using simspark::SExpr;

constexpr double kRad = M_PI / 180.0;

// One top-level list of an action message: how many items it has, its head (the first item when that is an atom,
// else empty), and which of its first six items are lists or else their atoms. Motors need six, beams four.
struct Expr {
  static constexpr size_t kKept = 6;
  size_t items = 0;
  std::string_view head;
  std::array<std::string_view, kKept> atoms;
  std::array<bool, kKept> list{};
};

// The numbers of `e` after its head, all finite; the error otherwise.
turf::Error Numbers(const Expr& e, size_t count, double* out) {
  if (e.items != count + 1 || e.items > Expr::kKept) return turf::Error::kBadArguments;
  for (size_t i = 1; i <= count; ++i) {
    if (e.list[i]) return turf::Error::kBadArguments;
    const NumberError n = simspark::ParseDouble(e.atoms[i], &out[i - 1]);
    if (n == NumberError::kNotFinite) return turf::Error::kNotFinite;
    if (n != NumberError::kOk) return turf::Error::kBadArguments;
  }
  return turf::Error::kOk;
}

turf::Error Motor(const Expr& e, const MjRobotModel& model, MotorAction* out) {
  const int joint = EffectorIndex(model, e.head);
  if (joint < 0) return turf::Error::kUnknownEffector;
  double v[5];
  if (const turf::Error error = Numbers(e, 5, v); error != turf::Error::kOk) return error;
  if (std::abs(v[0]) > kMaxAbsQDeg || std::abs(v[1]) > kMaxAbsDqDegS || v[2] < 0 || v[2] > kMaxKp || v[3] < 0 ||
      v[3] > kMaxKd || std::abs(v[4]) > kMaxAbsTau)
    return turf::Error::kOutOfRange;
  *out = MotorAction{joint, v[0] * kRad, v[1] * kRad, v[2], v[3], v[4]};
  return turf::Error::kOk;
}

turf::Error Beam(const Expr& e, BeamAction* out) {
  double v[3];
  if (const turf::Error error = Numbers(e, 3, v); error != turf::Error::kOk) return error;
  if (std::abs(v[0]) > kMaxAbsBeam || std::abs(v[1]) > kMaxAbsBeam) return turf::Error::kOutOfRange;
  *out = BeamAction{v[0], v[1], v[2]};
  return turf::Error::kOk;
}

// An action message read as the grammar walks it, each top-level list applied when it closes: no tree (agents send
// one every cycle, 22 of them every 4 ms at 5x real time).
class ActionReader final : public simspark::SExprVisitor {
 public:
  ActionReader(const MjRobotModel& model, ActionMessage* m) : model_(model), m_(m) {}

  void Open() override {
    if (depth_++ == 0) {
      e_ = Expr{};
    } else if (depth_ == 2) {
      Item({}, true);
    }
  }
  void Atom(std::string_view atom) override {
    if (depth_ == 1) Item(atom, false);
  }
  void Close() override {
    if (--depth_ == 0) Apply();
  }

 private:
  void Item(std::string_view atom, bool list) {
    if (e_.items == 0 && !list) e_.head = atom;
    if (e_.items < Expr::kKept) {
      e_.atoms[e_.items] = atom;
      e_.list[e_.items] = list;
    }
    ++e_.items;
  }

  void Apply() {
    const std::string_view head = e_.head;
    auto refuse = [&](turf::Error error) {
      m_->issues.push_back({error, fmt::format("({} ...): {}", head.substr(0, 32), turf::ErrorName(error))});
    };
    if (head == "syn") {
      m_->syn = true;
    } else if (head == "init") {
      refuse(turf::Error::kNotAllowed);  // only as the first message
    } else if (head == "say") {
      m_->say = true;
    } else if (head == "beam") {
      BeamAction beam;
      const turf::Error error = Beam(e_, &beam);
      if (error == turf::Error::kOk) {
        m_->beam = beam;
      } else {
        refuse(error);
      }
    } else if (e_.items == 6 && !head.empty()) {
      MotorAction motor;
      const turf::Error error = Motor(e_, model_, &motor);
      if (error == turf::Error::kOk) {
        m_->motors.push_back(motor);
      } else {
        refuse(error);
      }
    } else {
      refuse(head.empty() ? turf::Error::kMalformed : turf::Error::kUnknownEffector);
    }
  }

  const MjRobotModel& model_;
  ActionMessage* m_;
  size_t depth_ = 0;
  Expr e_;
};

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
  m.motors.reserve(model.joints.size());
  ActionReader reader(model, &m);
  size_t offset = 0;
  const simspark::SExprError error = simspark::WalkSExprs(payload, {}, reader, &offset);
  if (error == simspark::SExprError::kOk) return m;
  ActionMessage refused;  // all or nothing, as a parse
  refused.issues.push_back({turf::Error::kParse, simspark::SExprErrorAt(error, offset)});
  return refused;
}

}  // namespace turf::rcssservermj
