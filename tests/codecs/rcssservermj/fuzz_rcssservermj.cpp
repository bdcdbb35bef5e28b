// libFuzzer: the RCSSServerMJ agent and monitor decoders on untrusted bytes. The first byte picks the feed chunk
// size; the rest is a TCP byte stream cut into frames, each frame parsed as an init, as T1 and K1 actions and as
// monitor commands; the raw stream is parsed directly too. Whatever is accepted must hold the decoders' promises:
// finite numbers within their bounds, known effectors, a player number in 0..99.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>
#include <variant>

#include "codecs/rcssservermj/actions.h"
#include "codecs/rcssservermj/monitor.h"
#include "codecs/rcssservermj/robots.h"
#include "codecs/simspark/framing.h"

namespace {

namespace mj = turf::rcssservermj;

void Require(bool ok) {
  if (!ok) std::abort();
}

void CheckActions(std::string_view payload, const mj::MjRobotModel& model) {
  const mj::ActionMessage m = mj::ParseActions(payload, model);
  for (const mj::ActionIssue& issue : m.issues) Require(issue.error != turf::Error::kOk);
  for (const mj::MotorAction& motor : m.motors) {
    Require(motor.joint >= 0 && static_cast<size_t>(motor.joint) < model.joints.size());
    for (double v : {motor.q, motor.dq, motor.kp, motor.kd, motor.tau}) Require(std::isfinite(v));
    Require(motor.kp >= 0 && motor.kp <= mj::kMaxKp && motor.kd >= 0 && motor.kd <= mj::kMaxKd);
    Require(std::abs(motor.tau) <= mj::kMaxAbsTau);
  }
  if (m.beam) {
    Require(std::isfinite(m.beam->x) && std::isfinite(m.beam->y) && std::isfinite(m.beam->theta_deg));
    Require(std::abs(m.beam->x) <= mj::kMaxAbsBeam && std::abs(m.beam->y) <= mj::kMaxAbsBeam);
  }
}

void CheckMonitor(std::string_view payload) {
  const mj::MonitorMessage m = mj::ParseMonitorMessage(payload);
  for (const mj::MonitorCommand& c : m.commands) {
    if (const auto* agent = std::get_if<mj::AgentCommand>(&c)) {
      Require(agent->position.allFinite() && agent->position.cwiseAbs().maxCoeff() <= turf::kMaxLeggedPlacement &&
              std::abs(agent->orientation.norm() - 1.0) < 1e-6);
    }
    if (const auto* ball = std::get_if<mj::BallCommand>(&c))
      Require(std::abs(ball->x) <= turf::kMaxLeggedPlacement && std::abs(ball->y) <= turf::kMaxLeggedPlacement);
  }
}

void CheckAll(std::string_view payload) {
  mj::InitAction init;
  if (mj::ParseInit(payload, &init) == turf::Error::kOk) Require(init.player_no >= 0 && init.player_no <= 99);
  for (const mj::MjRobotModel& model : mj::Models()) CheckActions(payload, model);
  CheckMonitor(payload);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  const size_t chunk = 1 + data[0] % 64;
  const std::string_view stream(reinterpret_cast<const char*>(data + 1), size - 1);
  CheckAll(stream);
  turf::simspark::FrameDecoder decoder;
  for (size_t i = 0; i < stream.size(); i += chunk) {
    decoder.Feed(stream.data() + i, std::min(chunk, stream.size() - i));
    while (auto payload = decoder.Next()) CheckAll(*payload);
  }
  return 0;
}
