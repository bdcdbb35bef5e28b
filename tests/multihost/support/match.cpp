#include "tests/multihost/support/match.h"

namespace turf::test {

Match::Match(MatchSetup setup) : setup_(std::move(setup)) {
  grsim_port = FreePort();
  vision_port = FreePort();
}

std::unique_ptr<Process> Match::Start(const std::string& name, const std::string& binary, std::vector<std::string> args,
                                      bool bridge_host, const std::string& identity) const {
  args.insert(args.begin(), Built(binary));
  args.insert(args.end(), {"--domain", std::to_string(setup_.domain), "--prefix", setup_.prefix});
  if (!setup_.security.empty()) args.insert(args.end(), {"--security", setup_.security + "/" + identity});
  std::string log = setup_.prefix + "_" + name;
  if (setup_.hosts == nullptr) return std::make_unique<Process>(log, args, setup_.env);
  const std::string& ns = bridge_host ? setup_.hosts->bridge_ns() : setup_.hosts->sim_ns();
  return std::make_unique<Process>(log, setup_.hosts->In(ns, args, setup_.env));
}

std::unique_ptr<Process> Match::Sim(const std::string& tag) const {
  const std::string scene = std::string(TURF_SOURCE_DIR) + "/configs/scenes/" + setup_.scene + ".yaml";
  return Start("sim" + tag, "participants/sim/turf-sim", {"--scene", scene, "--realism", "ideal"}, false, "sim");
}

std::unique_ptr<Process> Match::Grsim(const std::string& tag) const {
  return Start("grsim" + tag, "participants/grsim_bridge/turf-grsim-bridge",
               {"--listen", "127.0.0.1", "--port", std::to_string(grsim_port), "--blue-status-port",
                std::to_string(FreePort()), "--yellow-status-port", std::to_string(FreePort())},
               true, "grsim-bridge");
}

std::unique_ptr<Process> Match::Vision(const std::string& tag) const {
  return Start("vision" + tag, "participants/vision_bridge/turf-vision-bridge",
               {"--address", "127.0.0.1", "--port", std::to_string(vision_port), "--geometry-every", "30"}, true,
               "vision-bridge");
}

}  // namespace turf::test
