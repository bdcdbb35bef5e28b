// libFuzzer: the SSL simulation protocol decoders on untrusted bytes. The
// first byte picks the port (control, blue, yellow, sync); the rest is the
// datagram. Whatever is accepted must hold the codec's promises: a refused
// datagram yields no command or request; every command is for a known robot
// of the port's team with finite values; every response encodes and parses back.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <vector>

#include "codecs/ssl_simulation/robot_control.h"
#include "codecs/ssl_simulation/simulator_command.h"
#include "codecs/ssl_simulation/step_planner.h"
#include "codecs/ssl_simulation/sync.h"
#include "tests/codecs/ssl_simulation/test_util.h"

namespace {

namespace sp = turf::simproto;
namespace ws = turf::wire::simulation;
namespace idl = turf::idl;

void Require(bool ok) {
  if (!ok) std::abort();
}

template <class Message>
void RequireParses(const std::vector<uint8_t>& bytes) {
  Message m;
  Require(m.ParseFromArray(bytes.data(), static_cast<int>(bytes.size())));
}

void CheckCommands(const sp::RobotControlDecode& d, sp::Port port, int per_team) {
  Require(d.commands.size() == d.wire_ids.size());
  if (d.error != sp::DecodeError::kOk) Require(d.commands.empty() && !d.errors.empty());
  for (const idl::SslRobotCommand& c : d.commands) {
    Require(c.id() < per_team);
    if (port == sp::Port::kBlue) Require(c.team() == idl::TEAM_BLUE);
    if (port == sp::Port::kYellow) Require(c.team() == idl::TEAM_YELLOW);
    for (double v :
         {c.velocity().x(), c.velocity().y(), c.velocity().z(), c.kick_speed(), c.chip_angle(), c.dribbler_speed()})
      Require(std::isfinite(v));
    for (double w : c.wheel_velocity()) Require(std::isfinite(w));
  }
}

void CheckRequests(const sp::SimulatorCommandDecode& d) {
  if (d.error != sp::DecodeError::kOk) Require(d.requests.empty() && !d.errors.empty());
  for (const idl::SimControl& r : d.requests) {
    for (double v : {r.ball().position().x(), r.ball().position().y(), r.ball().position().z(), r.ball().velocity().x(),
                     r.robot().position().x(), r.robot().position().y(), r.robot().orientation(), r.speed()})
      Require(std::isfinite(v));
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  static const idl::SslField field = sp::test::DivAField(11);
  static const idl::WorldState world = sp::test::World();
  const sp::ControlContext context{&field, &world, false};
  const uint8_t* bytes = data + 1;
  const size_t n = size - 1;
  switch (data[0] % 4) {
    case 0: {
      const sp::SimulatorCommandDecode d = sp::DecodeSimulatorCommand(bytes, n, context);
      CheckRequests(d);
      RequireParses<ws::SimulatorResponse>(sp::EncodeSimulatorResponse(d.errors));
      break;
    }
    case 1:
    case 2: {
      const sp::Port port = data[0] % 4 == 1 ? sp::Port::kBlue : sp::Port::kYellow;
      const sp::RobotControlDecode d = sp::DecodeRobotControl(bytes, n, port, 11);
      CheckCommands(d, port, 11);
      RequireParses<ws::RobotControlResponse>(sp::EncodeRobotControlResponse(d, {{{idl::TEAM_BLUE, 1}, true}}));
      break;
    }
    case 3: {
      const sp::SyncDecode d = sp::DecodeSyncRequest(bytes, n, context, 0.002);
      CheckCommands(d.robots, sp::Port::kSync, 11);
      CheckRequests(d.command);
      if (d.error != sp::DecodeError::kOk) Require(d.sim_step_ns == 0 && d.robots.commands.empty());
      if (d.error == sp::DecodeError::kOk) Require(d.sim_step_ns >= 0 && d.sim_step_ns <= 1'000'000'000);
      // Whatever was accepted plans a bounded, sane number of steps.
      static sp::StepPlanner planner;
      const uint32_t steps = planner.Plan(d.sim_step_ns, 2'000'000);
      Require(steps <= 501 && planner.carry_ns() >= -1'000'000 && planner.carry_ns() < 1'000'000);
      RequireParses<ws::SimulationSyncResponse>(sp::EncodeSyncResponse({}, field, d, {}, {}));
      break;
    }
  }
  return 0;
}
