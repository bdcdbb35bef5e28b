#include "participants/render/switch_command.h"

#include <spdlog/spdlog.h>
#include <turf/idl/CameraControlPubSubTypes.h>

#include <thread>

#include "dds/camera_topics.h"
#include "dds/vendor_participant.h"
#include "participants/common/participant_main.h"
#include "participants/common/process.h"

namespace turf {

int SendCameraSwitches(const RenderOptions& options, const std::vector<CameraControlRequest>& switches,
                       std::chrono::milliseconds wait) {
  dds::VendorParticipant participant(dds::VendorOptions{options.domain, options.name + "-switch", options.security,
                                                        /*large_samples=*/false, options.authentication_timeout()});
  const std::string topic = dds::CameraControlTopicName(options.prefix);
  auto writer = participant.MakeWriter<idl::CameraControlPubSubType>(topic);
  const auto deadline = std::chrono::steady_clock::now() + wait;
  while (writer->Matched() < 1 && std::chrono::steady_clock::now() < deadline && !StopRequested())
    std::this_thread::sleep_for(std::chrono::milliseconds(50));  // discovery: nothing to wait on but time
  if (StopRequested()) return kExitClean;  // asked to stop while waiting: nothing was sent, nothing is claimed
  if (writer->Matched() < 1) {
    spdlog::error("no turf-render reads {} on domain {} (is one running with this --prefix?)", topic, options.domain);
    return kExitFailure;
  }
  bool sent = false;
  for (int round = 0; round < 3 && !StopRequested(); ++round, sent = true) {
    if (round > 0) std::this_thread::sleep_for(std::chrono::milliseconds(200));
    for (const CameraControlRequest& r : switches) {
      idl::CameraControl c;
      c.robot(r.robot);
      c.camera(r.camera);
      c.enabled(r.enabled);
      c.rate_hz(r.rate_hz);
      c.source(options.name + " --switch");
      writer->Write(c);
    }
  }
  for (const CameraControlRequest& r : switches)
    if (sent)
      spdlog::info("{}/{} {} on {} ({} renderer(s) reading)", r.robot, r.camera,
                   r.enabled ? (r.rate_hz > 0 ? fmt::format("on at {} Hz", r.rate_hz) : std::string("on")) : "off",
                   topic, writer->Matched());
  spdlog::default_logger()->flush();
  return kExitClean;
}

}  // namespace turf
