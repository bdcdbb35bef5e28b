// libFuzzer: the SimSpark agent/trainer decoders on untrusted bytes. The first
// byte picks the feed chunk size; the rest is a TCP byte stream, cut into
// frames by FrameDecoder, each frame parsed as an agent message and as a
// trainer message. The raw stream is parsed directly too (most inputs are not
// framed). Whatever is accepted must hold the decoders' promises: finite
// numbers, values in range (trainer.h's ranges), nothing applied from an
// unparsable payload.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>
#include <variant>

#include "codecs/simspark/effectors.h"
#include "codecs/simspark/framing.h"
#include "codecs/simspark/nao_joints.h"
#include "codecs/simspark/trainer.h"
#include "core/input_limits.h"
#include "core/legged/placement_limits.h"

namespace {

namespace ss = turf::simspark;

void Require(bool ok) {
  if (!ok) std::abort();
}

void CheckAgent(std::string_view payload) {
  const ss::AgentMessage m = ss::ParseAgentMessage(payload);
  for (const ss::EffectorIssue& issue : m.issues) {
    Require(issue.error != ss::EffectorError::kOk);
    if (issue.error == ss::EffectorError::kParse) {
      Require(m.issues.size() == 1 && !m.scene && !m.init && !m.beam && m.hinges.empty() && !m.say && !m.syn &&
              !m.pass);
    }
  }
  if (m.scene) Require(m.scene->type >= 0 && m.scene->type < ss::kNaoTypes);
  if (m.init) Require(m.init->unum >= 0 && m.init->unum <= 99);
  if (m.beam) Require(std::isfinite(m.beam->x) && std::isfinite(m.beam->y) && std::isfinite(m.beam->rot_deg));
  if (m.say) Require(ss::IsValidSayMessage(*m.say));
  for (const ss::HingeEffector& h : m.hinges) {
    Require(std::isfinite(h.velocity));
    Require(ss::IsNaoHingeEffector(h.effector));
  }
}

bool Finite3(const std::array<double, 3>& v) {
  return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]);
}

// A placement the trainer may ask (trainer.h's ranges): finite, x and y within turf-sim's legged limit
// (core/legged/placement_limits.h), height from the ground up.
bool Placeable(const std::array<double, 3>& p) {
  return Finite3(p) && std::abs(p[0]) <= turf::kMaxLeggedPlacement && std::abs(p[1]) <= turf::kMaxLeggedPlacement &&
         p[2] >= 0 && p[2] <= turf::kMaxTeleportHeight;
}

void CheckTrainer(std::string_view payload) {
  const ss::TrainerMessage m = ss::ParseTrainerMessage(payload);
  for (const ss::TrainerIssue& issue : m.issues) {
    Require(!issue.error.empty());
    if (issue.error == "parse") Require(m.issues.size() == 1 && m.commands.empty());
  }
  auto unum_ok = [](int unum) { return unum >= 0 && unum <= 99; };
  for (const ss::TrainerCommand& c : m.commands) {
    Require(ss::TrainerCommandName(c)[0] != '\0');
    ss::IsMatchControl(c);
    if (const auto* a = std::get_if<ss::MoveAgent>(&c)) {
      Require(unum_ok(a->unum) && Placeable(a->pos) && (!a->yaw_deg || std::isfinite(*a->yaw_deg)));
    } else if (const auto* b = std::get_if<ss::SetBall>(&c)) {
      Require(b->pos || b->vel);
      Require(!b->pos || Placeable(*b->pos));
      Require(!b->vel || (Finite3(*b->vel) && std::hypot((*b->vel)[0], (*b->vel)[1], (*b->vel)[2]) <=
                                                  turf::kMaxTeleportSpeed * (1 + 1e-12)));
    } else if (const auto* p = std::get_if<ss::SetPlayModeCmd>(&c)) {
      Require(static_cast<int>(p->mode) >= 0 && p->mode < ss::PlayMode::kCount);
    } else if (const auto* t = std::get_if<ss::SetGameTime>(&c)) {
      Require(std::isfinite(t->time) && t->time >= 0 && t->time <= ss::kMaxTrainerTime);
    } else if (const auto* reset = std::get_if<ss::ResetTeamCmd>(&c)) {
      Require(reset->team != ss::TrainerTeam::kNone);
    } else if (const auto* s = std::get_if<ss::SetScoreCmd>(&c)) {
      Require(s->left || s->right);
      Require((!s->left || (*s->left >= 0 && *s->left <= 999)) && (!s->right || (*s->right >= 0 && *s->right <= 999)));
    } else if (const auto* k = std::get_if<ss::KillAgent>(&c)) {
      Require(unum_ok(k->unum));
    } else if (const auto* sel = std::get_if<ss::SelectAgent>(&c)) {
      Require(unum_ok(sel->unum));
    } else if (const auto* r = std::get_if<ss::ReposAgent>(&c)) {
      Require(unum_ok(r->unum));
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  const size_t chunk = size_t{data[0]} + 1;
  const char* stream = reinterpret_cast<const char*>(data + 1);
  const size_t length = size - 1;

  CheckAgent(std::string_view(stream, length));
  CheckTrainer(std::string_view(stream, length));

  // A small maximum so that the fuzzer also reaches kTooLarge.
  ss::FrameDecoder decoder(1024);
  std::string reframed;
  for (size_t at = 0; at < length; at += chunk) {
    decoder.Feed(stream + at, std::min(chunk, length - at));
    Require(decoder.buffered() <= 1024 + 4);
    while (std::optional<std::string> payload = decoder.Next()) {
      Require(!payload->empty() && payload->size() <= 1024);
      CheckAgent(*payload);
      CheckTrainer(*payload);
      reframed += ss::Frame(*payload);
    }
  }
  if (decoder.error() != ss::FrameError::kOk) Require(decoder.buffered() == 0);
  // What came out goes back in whole and comes out the same.
  ss::FrameDecoder again(1024);
  again.Feed(reframed.data(), reframed.size());
  std::string reframed_again;
  while (std::optional<std::string> payload = again.Next()) reframed_again += ss::Frame(*payload);
  Require(again.error() == ss::FrameError::kOk && reframed_again == reframed);
  return 0;
}
