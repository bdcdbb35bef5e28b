#include "codecs/simspark/effectors.h"

#include "codecs/simspark/nao_joints.h"
#include "codecs/simspark/sexpr.h"

namespace turf::simspark {

namespace {

constexpr size_t kMaxSay = 20;
constexpr int kMaxUnum = 99;

// Names from the wire are echoed in details, cut to a readable length.
std::string Name(std::string_view name) { return std::string(name.substr(0, 32)); }

// The arguments of `e` (the items after its head) when all are atoms.
bool AtomArgs(const SExpr& e, std::vector<std::string_view>* args) {
  args->clear();
  for (size_t i = 1; i < e.items.size(); ++i) {
    if (e.items[i].is_list) return false;
    args->push_back(e.items[i].atom);
  }
  return true;
}

// Exactly `n` numeric arguments.
EffectorError Numbers(const SExpr& e, size_t n, double* out) {
  std::vector<std::string_view> args;
  if (!AtomArgs(e, &args) || args.size() != n) return EffectorError::kBadArguments;
  EffectorError result = EffectorError::kOk;
  for (size_t i = 0; i < n; ++i) {
    const NumberError error = ParseDouble(args[i], &out[i]);
    if (error == NumberError::kBad) return EffectorError::kBadArguments;
    if (error == NumberError::kNotFinite) result = EffectorError::kNotFinite;
  }
  return result;
}

class Decoder {
 public:
  explicit Decoder(AgentMessage* message) : message_(message) {}

  void Predicate(const SExpr& e) {
    const std::string_view name = e.Head();
    if (name == "scene") return Scene(e);
    if (name == "init") return Init(e);
    if (name == "beam") return Beam(e);
    if (name == "say") return Say(e);
    if (name == "syn" || name == "pass") {
      if (e.items.size() != 1) return Issue(EffectorError::kBadArguments, Name(name) + ": takes no arguments");
      (name == "syn" ? message_->syn : message_->pass) = true;
      return;
    }
    if (IsNaoHingeEffector(name)) return Hinge(e);
    Issue(EffectorError::kUnknownEffector, name.empty() ? "(a list without a name)" : Name(name));
  }

 private:
  void Issue(EffectorError error, std::string detail) { message_->issues.push_back({error, std::move(detail)}); }

  void Scene(const SExpr& e) {
    std::vector<std::string_view> args;
    if (!AtomArgs(e, &args) || args.empty() || args.size() > 2)
      return Issue(EffectorError::kBadArguments, "scene: expected a path and an optional robot type");
    SceneEffector scene{std::string(args[0]), 0};
    if (args.size() == 2) {
      if (!ParseInt(args[1], &scene.type))
        return Issue(EffectorError::kBadArguments, "scene: robot type is not an integer");
      if (scene.type < 0 || scene.type >= kNaoTypes)
        return Issue(EffectorError::kBadRobotType, "scene: robot type " + std::to_string(scene.type));
    }
    message_->scene = std::move(scene);
  }

  void Init(const SExpr& e) {
    InitEffector init;
    bool has_team = false;
    for (size_t i = 1; i < e.items.size(); ++i) {
      const SExpr& part = e.items[i];
      const bool pair = part.is_list && part.items.size() == 2 && !part.items[1].is_list;
      if (pair && part.IsCall("unum")) {
        if (!ParseInt(part.items[1].atom, &init.unum) || init.unum < 0 || init.unum > kMaxUnum)
          return Issue(EffectorError::kBadArguments, "init: unum must be an integer in 0..99");
      } else if (pair && part.IsCall("teamname")) {
        init.team = part.items[1].atom;
        has_team = true;
      } else {
        return Issue(EffectorError::kBadArguments, "init: expected (unum N) and (teamname NAME)");
      }
    }
    if (!has_team) return Issue(EffectorError::kBadArguments, "init: no teamname");
    message_->init = std::move(init);
  }

  void Beam(const SExpr& e) {
    double v[3];
    const EffectorError error = Numbers(e, 3, v);
    if (error != EffectorError::kOk) return Issue(error, "beam: expected 3 finite numbers");
    message_->beam = BeamEffector{v[0], v[1], v[2]};
  }

  void Say(const SExpr& e) {
    if (e.items.size() != 2 || e.items[1].is_list || !IsValidSayMessage(e.items[1].atom))
      return Issue(EffectorError::kBadSay, "say: expected one word of 1..20 characters");
    message_->say = e.items[1].atom;
  }

  void Hinge(const SExpr& e) {
    double v = 0;
    const EffectorError error = Numbers(e, 1, &v);
    if (error != EffectorError::kOk) return Issue(error, e.items[0].atom + ": expected 1 finite number");
    message_->hinges.push_back({e.items[0].atom, v});
  }

  AgentMessage* message_;
};

}  // namespace

bool IsValidSayMessage(std::string_view message) {
  if (message.empty() || message.size() > kMaxSay) return false;
  for (const char c : message)
    if (c < 0x21 || c > 0x7E || c == '(' || c == ')') return false;
  return true;
}

AgentMessage ParseAgentMessage(std::string_view payload) {
  AgentMessage message;
  const SExprParse parse = ParseSExprs(payload);
  if (parse.error != SExprError::kOk) {
    message.issues.push_back({EffectorError::kParse,
                              std::string(SExprErrorName(parse.error)) + " at offset " + std::to_string(parse.offset)});
    return message;
  }
  Decoder decoder(&message);
  for (const SExpr& e : parse.exprs) decoder.Predicate(e);
  return message;
}

}  // namespace turf::simspark
